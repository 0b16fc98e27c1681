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
namespace glint::render {
struct RenderOptions;
}

namespace glint::app {

struct SceneRequest {
    std::string path;
    std::vector<std::string> include_dirs;  // the user's -I folders
    double clock = 0;
    int width = 320;
    int height = 240;
    // POV-Ray's animation identifiers and Declare=Name=Value (set from POV-Ray's options,
    // formats/pov/command_line.h).
    bool clock_on = false;
    double clock_delta = 1;
    std::optional<double> initial_clock, final_clock;
    int initial_frame = 1, final_frame = 1, frame_number = 0;
    std::vector<std::pair<std::string, double>> declares;
    // Resource limits (--max-*; docs/usage.md): passing one is exit 4, never a hang
    // or an exhausted machine. Defaults are pov::ParseOptions's.
    struct Limits {
        long long loop_iterations = 10'000'000;
        int recursion = 256;
        int include_depth = 64;
        long long array_size = 10'000'000;
        long long string_length = 100'000'000;
        long long triangles = 50'000'000;
        long long objects = 10'000'000;
        long long image_pixels = 1LL << 28;  // 16384 x 16384
        int parse_stack_mib = 256;
        long long memory_mib = 0;  // 0: three quarters of the machine's memory
    } limits;
};

// Registers the flags every scene-reading subcommand shares: SCENE, -I/--include (one folder
// each, repeatable), --clock, -W/--width and -H/--height (image_width/image_height), the
// resource limits (--max-loop-iterations, --max-recursion, ...). SCENE is
// optional for `render`, where POV-Ray's +I or an .ini may name it.
void add_scene_options(CLI::App& cmd, SceneRequest& request, bool scene_required = true);

// Throws glint::Error. Warnings go to stderr as `file:line:col: warning: ...` as they come;
// informational messages only when `verbose`.
scene::Scene load_scene(const SceneRequest& request, bool verbose);

// What the command line gave of the settings a Blender scene carries too.
struct GivenSettings {
    bool width = false, height = false, integrator = false, spp = false, seed = false,
         max_depth = false;
    bool adaptive = false;  // --adaptive and its settings (or the report's own: off)
};
// A Blender scene's render settings (its Cycles panel: filter, clamping, bounce limits,
// transparent film, volume steps) into `options`; the given ones stay as they are. `render`
// and `report` both read a Blender scene through this, so that they render the same image.
void apply_blender_render(const scene::BlenderRender& b, const GivenSettings& given,
                          render::RenderOptions* options);

}  // namespace glint::app
