#include "oiio_module.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <system_error>

#include "lamina/core/error.h"

namespace lamina::render {

namespace {

/// $LAMINA_OIIO_MODULE, else the build's module if it is there, else the one beside the binary
/// that holds lamina_render (the executable, or the Python extension; an installed or copied
/// lamina).
std::string modulePath() {
    if (const char* env = std::getenv("LAMINA_OIIO_MODULE"); env && *env) return env;
    const std::filesystem::path built = LAMINA_OIIO_MODULE_PATH;
    std::error_code ec;
    if (std::filesystem::exists(built, ec)) return built.string();
    std::filesystem::path binary;
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&modulePath), &info) && info.dli_fname)
        binary = info.dli_fname;
    if (binary.empty() || binary.is_relative())  // the executable, as it was started
        binary = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (binary.empty()) return built.string();
    return (binary.parent_path() / built.filename()).string();
}

struct LoadedModule {
    std::string path;
    const oiio_images::Functions* functions = nullptr;
    std::string error;  // why functions is null
};

LoadedModule load() {
    LoadedModule m;
    m.path = modulePath();
    // Never closed: the process uses it until it ends. RTLD_LOCAL keeps OpenImageIO's symbols
    // to the module.
    void* handle = ::dlopen(m.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = ::dlerror();
        m.error = why ? why : "cannot be loaded";
        return m;
    }
    using Entry = const oiio_images::Functions* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, oiio_images::kEntryPoint));
    if (!entry) {
        const char* why = ::dlerror();
        m.error = why ? why : "no entry point";
        return m;
    }
    const oiio_images::Functions* f = entry();
    if (!f || f->abiVersion != oiio_images::kAbiVersion) {
        m.error = "a module of another lamina build (interface version " +
                  std::to_string(f ? f->abiVersion : 0) + ", expected " +
                  std::to_string(oiio_images::kAbiVersion) + ")";
        return m;
    }
    m.functions = f;
    return m;
}

}  // namespace

const oiio_images::Functions& oiioModule(const std::filesystem::path& file,
                                         const std::string& action) {
    static const LoadedModule module = load();  // once, thread-safe (C++11 statics)
    if (!module.functions)
        throw InputError(
            file.string() + ": " + action + " " +
            (file.extension().empty() ? std::string("extension-less") : file.extension().string()) +
            " images needs lamina's OpenImageIO module (" + module.path + "): " + module.error);
    return *module.functions;
}

}  // namespace lamina::render
