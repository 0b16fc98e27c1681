// `glint compare A B`: the golden-test metric of VALIDATION.md on two image files, plus the
// Monte Carlo metrics (relMSE, linear RMSE) on linear values.
#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "app/cli_common.h"
#include "app/commands.h"
#include "io/image_compare.h"

namespace glint::app {

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args) {
    CLI::App* cmd =
        app.add_subcommand("compare", "Compare two images; exit 0 if they agree, 6 if not");
    cmd->footer(
        "Compare two images (PNG/TIFF/JPEG/EXR/HDR): the 8-bit metrics within, rmse, max, mae, "
        "ssim (float files sRGB-encoded first), and on linear values (8-bit files "
        "sRGB-decoded) relmse = mean((A-B)^2/(B^2+0.01)) and rmse_linear; exit 0 if they "
        "agree (within >= --min-fraction; with --close also SSIM >= 0.95 and MAE <= 2%), 6 if "
        "not");
    cmd->add_option("A", args.a, "First image")->required();
    cmd->add_option("B", args.b, "Second image (the reference)")->required();
    cmd->add_option("--diff", args.diff,
                    "Write a difference image: .exr gets |A-B| of the linear values unscaled, "
                    "any other format |A-B| of the 8-bit values scaled so the largest is white");
    cmd->add_option("--tolerance", args.tolerance,
                    "Largest channel difference (in 1/255) a pixel may have to count as within")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 255.0));
    cmd->add_option("--min-fraction", args.min_fraction,
                    "Fraction of pixels that must be within the tolerance")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_flag("--close", args.close,
                  "Also agree when SSIM >= 0.95 and MAE <= 2% of full scale (VALIDATION.md's "
                  "close, for renders that draw their own random numbers)");
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
    const io::LinearImage la = io::read_linear(args.a);
    const io::LinearImage lb = io::read_linear(args.b);
    const io::LinearMetrics lin = io::compare_linear(la, lb);
    r.relmse = lin.relmse;
    r.rmse_linear = lin.rmse;
    if (lin.nonfinite > 0)
        std::fprintf(stderr, "glint compare: warning: %lld non-finite values left out\n",
                     lin.nonfinite);
    if (!args.diff.empty()) {
        std::string ext = std::filesystem::path(args.diff).extension().string();
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (ext == ".exr")
            io::write_linear_exr(io::linear_difference(la, lb), args.diff);
        else
            io::write_rgb8_png(io::difference_image(a, b), args.diff);
    }
    std::printf("%s\n", io::format_compare_line(r).c_str());
    std::fflush(stdout);
    const bool close = args.close && r.ssim >= 0.95 && r.mae <= 0.02 * 255;
    return r.within_fraction >= args.min_fraction || close ? kExitOk : kExitDiffer;
}

}  // namespace glint::app
