// The glint subcommands. Each registers its flags on the CLI11 app and runs from a plain
// struct of parsed arguments, returning the process exit code (cli_common.h).
#pragma once

#include <string>
#include <vector>

#include "app/scene_loading.h"

namespace CLI {
class App;
}

namespace glint::app {

struct RenderArgs {
    SceneRequest scene;  // SCENE, -I, --clock, --width/--height (also the image size)
    std::string output;
    std::string aa = "none";
    int threads = 0;
    bool verbose = false;
    std::string progress;  // empty: bar on a terminal, none otherwise
};

struct IrArgs {
    SceneRequest scene;
};

struct CompareArgs {
    std::string a;
    std::string b;
    std::string diff;
    double tolerance = 2;
    double min_fraction = 0.99;
};

CLI::App* add_render_command(CLI::App& app, RenderArgs& args);
CLI::App* add_ir_command(CLI::App& app, IrArgs& args);
CLI::App* add_compare_command(CLI::App& app, CompareArgs& args);

int run_render(const RenderArgs& args);
int run_ir(const IrArgs& args);
int run_compare(const CompareArgs& args);

}  // namespace glint::app
