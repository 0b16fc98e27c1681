#include "app/cli_common.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <thread>

namespace glint::app {

namespace {

// A signal handler can only reach static storage; this flag is the one piece of global state
// in glint, and only the CLI has it. The library sees it as RenderOptions::cancel.
std::atomic<bool> g_cancel{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_signal(int sig) {
    g_cancel.store(true);
    std::signal(sig, SIG_DFL);  // a second signal ends the process the usual way
}

}  // namespace

int exit_code_for(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::Usage:
            return kExitUsage;
        case ErrorKind::Scene:
            return kExitScene;
        case ErrorKind::MissingFile:
            return kExitMissingFile;
        case ErrorKind::Render:
            return kExitRender;
        case ErrorKind::Output:
            return kExitOutput;
        case ErrorKind::Cancelled:
            return kExitInterrupted;
    }
    return kExitRender;
}

int report_error(const Error& e) {
    if (e.kind() == ErrorKind::Cancelled)
        std::fputs("glint: interrupted; nothing written\n", stderr);
    else
        std::fputs(format_error(e).c_str(), stderr);
    std::fflush(stderr);
    return exit_code_for(e.kind());
}

void install_signal_handlers() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}

const std::atomic<bool>& cancel_flag() { return g_cancel; }

void cancel_when_parent_exits() {
    const pid_t parent = ::getppid();
    // Polled: portable, and a fifth of a second is nothing beside a render. The thread ends
    // with the process.
    std::thread([parent] {
        while (!g_cancel.load()) {
            if (::getppid() != parent) {
                g_cancel.store(true);
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
    }).detach();
}

std::vector<std::string> include_search_path(const std::vector<std::string>& user_dirs) {
    std::vector<std::string> dirs = user_dirs;
    std::error_code ec;
    if (std::filesystem::is_directory(kPovIncludeDir, ec)) dirs.emplace_back(kPovIncludeDir);
    return dirs;
}

}  // namespace glint::app
