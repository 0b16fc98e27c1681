// The POV-Ray 3.7 scene language importer: scanner -> directives (#include, #declare,
// #if, #while, #macro) -> expressions -> objects and materials -> scene::Scene.
// GRAMMAR.md beside this file lists the supported subset.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/log.h"
#include "scene/object_query.h"
#include "scene/scene.h"

namespace glint::pov {

struct ParseOptions {
    // Searched after the scene file's own folder, in order; the CLI appends
    // /usr/share/povray-3.7/include when it exists.
    std::vector<std::string> include_dirs;
    double clock = 0;
    // POV-Ray's animation identifiers: clock_on is 1 when a clock was given (+K, --clock or
    // an animation); `glint render`'s animation loop sets the others for each frame.
    // initial_clock/final_clock read as `clock` when unset.
    bool clock_on = false;
    double clock_delta = 1;
    std::optional<double> initial_clock, final_clock;
    int initial_frame = 1, final_frame = 1, frame_number = 0;
    // Declare=Name=Value (POV-Ray command line or .ini): floats declared before the scene.
    std::vector<std::pair<std::string, double>> declares;
    // image_width / image_height as the scene sees them.
    int image_width = 320;
    int image_height = 240;
    // Resource limits: exceeded limits are errors (ErrorKind::Render, exit 4, at the place in
    // the scene), never hangs or exhausted memory. The CLI flags named in the messages set them.
    long long max_loop_iterations = 10'000'000;  // per #while/#for loop (--max-loop-iterations)
    int max_include_depth = 64;                  // --max-include-depth
    int max_macro_depth = 256;                   // --max-recursion
    long long max_tokens = 2'000'000'000;
    long long max_array_elements = 10'000'000;   // per array, all dimensions (--max-array-size)
    long long max_string_length = 100'000'000;   // bytes per string value (--max-string-length)
    long long max_triangles = 50'000'000;        // mesh triangles in the scene (--max-triangles)
    long long max_objects = 10'000'000;          // top-level objects in the scene (--max-objects)
    // Stack the recursive-descent parser may use, in MiB (--max-parse-stack): how deeply
    // parentheses, objects, blocks and macro calls can nest. The parser runs on a thread of
    // its own whose stack is this plus a margin, reserved but only touched as deep as used.
    int max_parse_stack_mib = 256;
    // Parse on the calling thread instead (the fuzz targets, which parse millions of inputs and
    // would spend a third of their time making threads): the budget must then fit well inside
    // the caller's own stack.
    bool parse_on_calling_thread = false;
    // Memory the process may hold while the scene is parsed, in MiB (--max-memory; 0: no
    // limit). Checked every few thousand tokens, so arrays, strings and meshes built by loops
    // stop with an error instead of taking the machine's memory.
    long long max_memory_mib = 0;
    // Set (by SIGINT/SIGTERM in the CLI): parsing stops with ErrorKind::Cancelled within a few
    // thousand tokens, so a long #while loop or include chain can be interrupted too.
    const std::atomic<bool>* cancel = nullptr;
    // Hooks the application installs for what lives above the importer (formats/ must not
    // depend on render/); a null hook makes the feature that needs it "not supported".
    // Pattern and pigment functions called at parse time (scene::FunctionEnv::pattern); `user`
    // is the parser's scene::FunctionEnv (the functions declared so far, noise_generator).
    void (*pattern_hook)(const void* user, const scene::Function& f, const Vec3& p,
                         double out[5]) = nullptr;
    // trace(), inside() and min_extent()/max_extent() at parse time (scene/object_query.h):
    // the application prepares the object with the renderer's geometry. Unset: those
    // functions are not supported.
    scene::ObjectPrepareFn prepare_object;
};

// Throws glint::Error (ErrorKind::Scene or MissingFile) with the FileLoc of the problem.
scene::Scene parse_file(const std::string& path, const ParseOptions& options, Diagnostics& diag);
// `name` is used as the file name in locations.
scene::Scene parse_string(const std::string& text, const std::string& name,
                          const ParseOptions& options, Diagnostics& diag);

}  // namespace glint::pov
