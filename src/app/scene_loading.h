// Reading a scene for a subcommand: checks the file, builds ParseOptions from the flags
// (search path, clock, image size), prints the parser's warnings on stderr, validates.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace CLI {
class App;
}

namespace glint::app {

struct SceneRequest {
    std::string path;
    std::vector<std::string> include_dirs;  // the user's -I folders
    double clock = 0;
    int width = 320;
    int height = 240;
    // POV-Ray's animation identifiers and Declare=Name=Value (pov_options.h sets these).
    bool clock_on = false;
    double clock_delta = 1;
    std::optional<double> initial_clock, final_clock;
    int initial_frame = 1, final_frame = 1, frame_number = 0;
    std::vector<std::pair<std::string, double>> declares;
};

// Registers the flags every scene-reading subcommand shares: SCENE, -I/--include (one folder
// each, repeatable), --clock, -W/--width and -H/--height (image_width/image_height). SCENE is
// optional for `render`, where POV-Ray's +I or an .ini may name it.
void add_scene_options(CLI::App& cmd, SceneRequest& request, bool scene_required = true);

// Throws glint::Error. Warnings go to stderr as `file:line:col: warning: ...` as they come;
// informational messages only when `verbose`.
scene::Scene load_scene(const SceneRequest& request, bool verbose);

}  // namespace glint::app
