// `glint compare A B`: the golden-test metric of VALIDATION.md on two image files.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/cli_common.h"
#include "app/commands.h"
#include "io/image_compare.h"

namespace glint::app {

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "compare", "Compare two images in 8-bit space; exit 0 if they agree, 6 if not");
    cmd->add_option("A", args.a, "First image")->required();
    cmd->add_option("B", args.b, "Second image (the reference)")->required();
    cmd->add_option("--diff", args.diff, "Write |A-B|, scaled to its maximum, as PNG");
    cmd->add_option("--tolerance", args.tolerance,
                    "Largest channel difference (in 1/255) a pixel may have to count as within")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 255.0));
    cmd->add_option("--min-fraction", args.min_fraction,
                    "Fraction of pixels that must be within the tolerance")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    return cmd;
}

int run_compare(const CompareArgs& args) {
    io::Rgb8Image a = io::read_rgb8(args.a);
    io::Rgb8Image b = io::read_rgb8(args.b);
    if (a.width != b.width || a.height != b.height) {
        // Different sizes cannot agree: report it as a difference, not as a usage error, so
        // a golden test fails with a readable reason.
        std::fprintf(stderr, "glint compare: error: image sizes differ: %s is %dx%d, %s is %dx%d\n",
                     args.a.c_str(), a.width, a.height, args.b.c_str(), b.width, b.height);
        return kExitDiffer;
    }
    io::CompareResult r = io::compare_images(a, b, args.tolerance);
    if (!args.diff.empty()) io::write_rgb8_png(io::difference_image(a, b), args.diff);
    std::printf("%s\n", io::format_compare_line(r).c_str());
    std::fflush(stdout);
    return r.within_fraction >= args.min_fraction ? kExitOk : kExitDiffer;
}

}  // namespace glint::app
