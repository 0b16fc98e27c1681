// glint: the command-line front end. It only parses flags and dispatches; each subcommand
// lives in its own file (render_command.cpp, ir_command.cpp, compare_command.cpp,
// report_command.cpp, convert_command.cpp, merge_command.cpp, farm_command.cpp).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"

int main(int argc, char** argv) {
    using namespace glint::app;
    CLI::App app("glint: renders POV-Ray 3.7 scenes and OBJ/MTL models", "glint");
    app.require_subcommand(1);
    app.set_version_flag("--version", "glint 0.1.0");

    RenderArgs render_args;
    IrArgs ir_args;
    CompareArgs compare_args;
    ReportArgs report_args;
    ConvertArgs convert_args;
    MergeArgs merge_args;
    FarmArgs farm_args;
    CLI::App* render = add_render_command(app, render_args);
    CLI::App* ir = add_ir_command(app, ir_args);
    CLI::App* compare = add_compare_command(app, compare_args);
    CLI::App* report = add_report_command(app, report_args);
    CLI::App* convert = add_convert_command(app, convert_args);
    CLI::App* merge = add_merge_command(app, merge_args);
    CLI::App* farm = add_farm_command(app, farm_args);

    // POV-Ray's switches and .ini files (`glint render +W640 scene.ini`) are not CLI11 flags:
    // they are taken out first and read in order by run_render.
    std::vector<std::string> all(argv, argv + argc);
    std::vector<std::string> rest = take_pov_arguments(all, render_args.pov_args);
    std::vector<char*> rest_argv;
    for (std::string& a : rest) rest_argv.push_back(a.data());
    try {
        app.parse(static_cast<int>(rest_argv.size()), rest_argv.data());
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // CLI11's own exit codes differ from the contract: every usage error is 1.
        app.exit(e);
        return kExitUsage;
    }

    try {
        if (render->parsed()) return run_render(render_args);
        if (ir->parsed()) return run_ir(ir_args);
        if (compare->parsed()) return run_compare(compare_args);
        if (report->parsed()) return run_report(report_args);
        if (convert->parsed()) return run_convert(convert_args);
        if (merge->parsed()) return run_merge(merge_args);
        if (farm->parsed()) return run_farm(farm_args);
    } catch (const glint::Error& e) {
        return report_error(e);
    } catch (const std::bad_alloc&) {
        std::fputs("glint: error: out of memory\n", stderr);
        return kExitRender;
    } catch (const std::exception& e) {
        // Library code throws glint::Error; anything else is a bug, reported as a render failure.
        std::fprintf(stderr, "glint: error: internal error: %s\n", e.what());
        return kExitRender;
    }
    return kExitUsage;
}
