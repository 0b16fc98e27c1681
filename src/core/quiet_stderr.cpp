#include "core/quiet_stderr.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <mutex>

namespace glint {
namespace {

std::mutex g_mutex;
int g_depth = 0;     // QuietStderr objects alive
int g_saved = -1;    // the real stderr while g_depth > 0

}  // namespace

QuietStderr::QuietStderr() {
    std::lock_guard<std::mutex> lock(g_mutex);
    if (g_depth++ > 0) return;
    std::fflush(stderr);
    g_saved = ::dup(STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (g_saved >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
    if (null >= 0) ::close(null);
}

QuietStderr::~QuietStderr() {
    std::lock_guard<std::mutex> lock(g_mutex);
    if (--g_depth > 0) return;
    std::fflush(stderr);
    if (g_saved >= 0) {
        ::dup2(g_saved, STDERR_FILENO);
        ::close(g_saved);
        g_saved = -1;
    }
}

std::string first_line_of(std::string text) {
    text = text.substr(0, text.find('\n'));
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '.'))
        text.pop_back();
    return text.empty() ? "unknown error" : text;
}

}  // namespace glint
