# Warnings for lamina's own targets only (third-party headers are included as SYSTEM).
function(lamina_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow=local -Wnon-virtual-dtor
                                           -Wno-missing-field-initializers)
endfunction()
