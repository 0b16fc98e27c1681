// The glint subcommands. Each registers its flags on the CLI11 app and runs from a plain
// struct of parsed arguments, returning the process exit code (cli_common.h).
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace glint::app {

struct RenderArgs {
    std::string scene;
    std::string output;
    int width = 320;
    int height = 240;
    std::string aa = "none";
    int threads = 0;
    std::vector<std::string> include_dirs;
    bool verbose = false;
    std::string progress;  // empty: bar on a terminal, none otherwise
    double clock = 0;
};

struct IrArgs {
    std::string scene;
    std::vector<std::string> include_dirs;
    double clock = 0;
    int width = 320;
    int height = 240;
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
