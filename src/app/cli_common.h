// What every glint subcommand shares: the exit codes of the CLI contract (in docs/usage.md),
// turning glint::Error into a message and an exit code, the interrupt flag set by
// SIGINT/SIGTERM, and the include search path.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "core/error.h"

namespace glint::app {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 1;
constexpr int kExitScene = 2;
constexpr int kExitMissingFile = 3;
constexpr int kExitRender = 4;
constexpr int kExitOutput = 5;
constexpr int kExitDiffer = 6;
constexpr int kExitInterrupted = 130;

// POV-Ray's standard include folder (Debian's povray-includes), searched last.
inline constexpr const char* kPovIncludeDir = "/usr/share/povray-3.7/include";

int exit_code_for(ErrorKind kind);

// Prints format_error(e) on stderr and returns the exit code for its kind.
int report_error(const Error& e);

// The first SIGINT/SIGTERM sets the flag (the renderer stops at the next tile and nothing is
// written); a second one terminates at once with the default action.
void install_signal_handlers();
const std::atomic<bool>& cancel_flag();

// --exit-with-parent: sets the flag, as SIGTERM does, once the process that started glint has
// ended (its parent pid changes: the process was re-parented). A program that runs glint (the
// Blender add-on) may crash or be killed, and its glint must not render on for nobody.
void cancel_when_parent_exits();

// The user's -I folders, then /usr/share/povray-3.7/include when it exists.
std::vector<std::string> include_search_path(const std::vector<std::string>& user_dirs);

}  // namespace glint::app
