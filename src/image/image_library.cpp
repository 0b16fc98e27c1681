#include "image/image_library.h"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <mutex>

#include "core/error.h"

#ifndef GLINT_OIIO_MODULE_BUILT
#define GLINT_OIIO_MODULE_BUILT ""
#endif

namespace glint {
namespace {

constexpr const char* kModuleName = "libglint_oiio.so";

std::atomic<const ImageLibrary*> g_library{nullptr};

std::string executable_dir() {
    std::string buf(4096, '\0');
    const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
    if (n <= 0) return {};
    buf.resize(static_cast<size_t>(n));
    const size_t slash = buf.rfind('/');
    return slash == std::string::npos ? std::string() : buf.substr(0, slash);
}

const ImageLibrary* load() {
    std::vector<std::string> candidates;
    if (const char* env = std::getenv("GLINT_IMAGE_MODULE"); env && *env) {
        candidates.emplace_back(env);
    } else {
        const std::string dir = executable_dir();
        if (!dir.empty()) candidates.push_back(dir + "/" + kModuleName);
        if (*GLINT_OIIO_MODULE_BUILT) candidates.emplace_back(GLINT_OIIO_MODULE_BUILT);
    }
    std::string why;
    for (const std::string& path : candidates) {
        if (::access(path.c_str(), R_OK) != 0) continue;
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* e = ::dlerror();
            why = e ? e : "dlopen failed";
            continue;
        }
        using Entry = const ImageLibrary* (*)();
        auto entry = reinterpret_cast<Entry>(::dlsym(handle, "glint_image_library_v1"));
        if (!entry) {
            why = path + " has no glint_image_library_v1";
            continue;
        }
        return entry();  // the module stays loaded for the life of the process
    }
    std::string looked;
    for (const std::string& c : candidates) looked += (looked.empty() ? "" : ", ") + c;
    throw Error(ErrorKind::Output, {},
                "cannot load glint's image module (OpenImageIO), looked for " + looked +
                    (why.empty() ? "" : ": " + why));
}

}  // namespace

const ImageLibrary& image_library() {
    if (const ImageLibrary* lib = g_library.load(std::memory_order_acquire)) return *lib;
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    if (const ImageLibrary* lib = g_library.load(std::memory_order_relaxed)) return *lib;
    const ImageLibrary* lib = load();
    g_library.store(lib, std::memory_order_release);
    return *lib;
}


}  // namespace glint
