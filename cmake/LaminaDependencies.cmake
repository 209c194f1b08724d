# Every third-party dependency is found through its own CMake config package. A missing one
# stops the configuration with the Debian package that provides it and the set-up command.
set(LAMINA_SETUP_HINT "run `bash scripts/setup.sh` (as root) to install every dependency")

macro(lamina_require package debian_package)
  find_package(${package} ${ARGN} CONFIG QUIET)
  if(NOT ${package}_FOUND)
    message(FATAL_ERROR
      "lamina: CMake package '${package}' not found. It comes with the Debian package "
      "'${debian_package}': ${LAMINA_SETUP_HINT}.")
  endif()
endmacro()

lamina_require(glm libglm-dev)
lamina_require(nlohmann_json nlohmann-json3-dev)
lamina_require(yaml-cpp libyaml-cpp-dev)

# zlib ships CMake's FindZLIB module, not a config package: gzip-compressed input files
# (lamina_core's gzip_file.h: .ply.gz meshes, .pbrt.gz scene files).
find_package(ZLIB QUIET)
if(NOT ZLIB_FOUND)
  message(FATAL_ERROR "lamina: zlib not found. It comes with the Debian package "
    "'zlib1g-dev': ${LAMINA_SETUP_HINT}.")
endif()
if(LAMINA_BUILD_APP)
  lamina_require(embree libembree-dev 3)
  lamina_require(TBB libtbb-dev)
  lamina_require(OpenImageIO libopenimageio-dev)
  lamina_require(OpenEXR libopenexr-dev)
  # Debian 12's OpenImageIO config lists /usr/include/opencv4 among its include directories
  # although OpenImageIO's headers need no OpenCV; CMake refuses a non-existent path. Keep
  # only the directories that exist.
  foreach(target OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
    if(TARGET ${target})
      get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
      if(dirs)
        set(existing "")
        foreach(dir IN LISTS dirs)
          if(EXISTS "${dir}" OR dir MATCHES "^\\$<")
            list(APPEND existing "${dir}")
          endif()
        endforeach()
        set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${existing}")
      endif()
    endif()
  endforeach()
  lamina_require(CLI11 libcli11-dev)
  lamina_require(tinyobjloader libtinyobjloader-dev)
  lamina_require(pugixml libpugixml-dev)
  if(LAMINA_BUILD_PYTHON AND NOT LAMINA_SANITIZE AND NOT LAMINA_FUZZ)
    # The system interpreter, whatever python3 comes first on PATH (pyenv, a venv): Debian's
    # pybind11, NumPy and pytest are installed for it.
    set(LAMINA_PYTHON "/usr/bin/python3" CACHE FILEPATH "The interpreter of the Python module")
    set(Python3_EXECUTABLE "${LAMINA_PYTHON}")
    find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
    if(NOT Python3_FOUND)
      message(FATAL_ERROR
        "lamina: the Python module needs ${LAMINA_PYTHON} and its headers (Debian package "
        "'python3-dev'): ${LAMINA_SETUP_HINT}, or configure with -DLAMINA_BUILD_PYTHON=OFF.")
    endif()
    lamina_require(pybind11 pybind11-dev)
  endif()
endif()
if(LAMINA_BUILD_TESTS)
  lamina_require(GTest libgtest-dev)
endif()
if(LAMINA_BUILD_BENCHMARKS)
  lamina_require(benchmark libbenchmark-dev)
endif()

# The CIE tables come from Debian's colord-data at build time (never copied into the repo).
set(LAMINA_COLORD_DIR "/usr/share/colord" CACHE PATH "Where colord-data installed its tables")
if(NOT EXISTS "${LAMINA_COLORD_DIR}/cmf/CIE1931-2deg-XYZ.cmf"
   OR NOT EXISTS "${LAMINA_COLORD_DIR}/illuminant/CIE-D65.sp")
  message(FATAL_ERROR
    "lamina: CIE tables not found under ${LAMINA_COLORD_DIR} (cmf/CIE1931-2deg-XYZ.cmf, "
    "illuminant/CIE-D65.sp). They come with the Debian package 'colord-data': "
    "${LAMINA_SETUP_HINT}.")
endif()

find_package(Python3 COMPONENTS Interpreter QUIET)
