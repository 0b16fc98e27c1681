// Cycles cross-check (issue 4): renders a scene of tests/cycles/scenes with glint's path
// tracer at the same samples per pixel as one Cycles seed image and applies the per-pixel
// Z-test of VALIDATION.md against the Cycles reference mean and its standard error
// (tests/cycles/ref, made by make_scenes.py --references):
//   z = (glint - ref) / sqrt(var_glint + var_ref)   per pixel and channel,
// a pixel is accepted when all three |z| stay under the Sidak-corrected threshold for
// alpha = 0.01 over every value of the image (as Mitsuba's render tests), and the scene passes
// when at least 99.75% of the pixels are accepted. var_glint is the variance of glint's mean:
// from glint's --variance output where glint has it, else from M renders with different
// seeds (each spp / M samples), whose sample variance over M gives it.
//
//   cycles_ztest render GLINT SCENE.pov REF_MEAN.exr REF_STDERR.exr OUT_DIR [spp] [max_depth]
//   cycles_ztest compare GLINT.exr GLINT_VAR_OF_MEAN.exr REF_MEAN.exr REF_STDERR.exr [OUT_DIR]
// Exit 0 on pass, 1 on fail, 2 on a usage or I/O error. On failure OUT_DIR gets NAME_z.exr
// (|z| per channel) next to glint's image.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/image_compare.h"

namespace fs = std::filesystem;
using glint::io::LinearImage;

namespace {

constexpr double kAlpha = 0.01;
constexpr double kMinAccepted = 0.9975;
constexpr int kSeedImages = 8;  // glint renders without --variance
constexpr long long kListRejected = 40;  // rejected pixels printed with their values

// |z| with P(|Z| > z) = p for a standard normal Z: erfc(z / sqrt 2) = p, by bisection.
double two_sided_threshold(double p) {
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (std::erfc(mid / std::sqrt(2.0)) > p) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

struct ZResult {
    long long pixels = 0;
    long long accepted = 0;
    double threshold = 0;
    double relmse = 0;
    double worst_z = 0;
    int worst_x = 0, worst_y = 0;
    LinearImage z;  // |z| per value
};

ZResult z_test(const LinearImage& x, const LinearImage& var_x, const LinearImage& ref,
               const LinearImage& stderr_ref) {
    auto same = [&](const LinearImage& a, const char* what) {
        if (a.width != ref.width || a.height != ref.height)
            throw glint::Error(glint::ErrorKind::Usage, {},
                               std::string(what) + " is " + std::to_string(a.width) + "x" +
                                   std::to_string(a.height) + ", the reference " +
                                   std::to_string(ref.width) + "x" + std::to_string(ref.height));
    };
    same(x, "glint's image");
    same(var_x, "glint's variance");
    same(stderr_ref, "the reference's standard error");
    ZResult r;
    r.pixels = static_cast<long long>(ref.width) * ref.height;
    const double n = static_cast<double>(r.pixels) * 3;
    r.threshold = two_sided_threshold(-std::expm1(std::log1p(-kAlpha) / n));
    r.z = ref;
    double rel = 0;
    long long rejected = 0;
    for (long long p = 0; p < r.pixels; ++p) {
        bool ok = true;
        for (int c = 0; c < 3; ++c) {
            const size_t i = static_cast<size_t>(p) * 3 + c;
            const double g = x.rgb[i], m = ref.rgb[i];
            const double s = stderr_ref.rgb[i];
            // The reference is stored as half floats: its rounding (a uniform error of one
            // half-float step, 2^-10 relative) counts as variance too.
            const double q = std::fabs(m) * std::ldexp(1.0, -10);
            const double var = std::max(0.0, double(var_x.rgb[i])) + s * s + q * q / 12;
            const double d = g - m;
            rel += d * d / (m * m + 0.01);
            double z;
            if (!std::isfinite(g) || !std::isfinite(var)) z = 1e30;
            else if (var > 0) z = std::fabs(d) / std::sqrt(var);
            else z = std::fabs(d) <= 1e-6 ? 0 : 1e30;
            r.z.rgb[i] = static_cast<float>(std::min(z, 1e30));
            if (z > r.threshold) ok = false;
            if (z > r.worst_z) {
                r.worst_z = z;
                r.worst_x = static_cast<int>(p % ref.width);
                r.worst_y = static_cast<int>(p / ref.width);
            }
        }
        if (ok) {
            ++r.accepted;
        } else if (++rejected <= kListRejected) {
            const size_t i = static_cast<size_t>(p) * 3;
            std::printf("  rejected %lld,%lld: glint %.4g %.4g %.4g (sd %.3g %.3g %.3g), "
                        "cycles %.4g %.4g %.4g (sd %.3g %.3g %.3g)\n",
                        p % ref.width, p / ref.width, x.rgb[i], x.rgb[i + 1], x.rgb[i + 2],
                        std::sqrt(std::max(0.0f, var_x.rgb[i])),
                        std::sqrt(std::max(0.0f, var_x.rgb[i + 1])),
                        std::sqrt(std::max(0.0f, var_x.rgb[i + 2])), ref.rgb[i], ref.rgb[i + 1],
                        ref.rgb[i + 2], stderr_ref.rgb[i], stderr_ref.rgb[i + 1],
                        stderr_ref.rgb[i + 2]);
        }
    }
    r.relmse = rel / n;
    return r;
}

bool glint_has_variance(const std::string& glint) {
    const std::string cmd = "\"" + glint + "\" render --help 2>&1";
    FILE* f = popen(cmd.c_str(), "r");
    if (!f) return false;
    std::string text;
    char buf[4096];
    size_t got;
    while ((got = fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, got);
    pclose(f);
    return text.find("--variance") != std::string::npos;
}

void run(const std::string& cmd) {
    std::printf("+ %s\n", cmd.c_str());
    std::fflush(stdout);
    const int rc = std::system(cmd.c_str());
    if (rc != 0)
        throw glint::Error(glint::ErrorKind::Usage, {},
                           "command failed (" + std::to_string(rc) + "): " + cmd);
}

// glint's mean at `spp` samples and the variance of that mean.
void render_glint(const std::string& glint, const std::string& scene, const fs::path& out_dir,
                  int width, int height, int spp, int max_depth, LinearImage* mean,
                  LinearImage* var) {
    const std::string stem = fs::path(scene).stem().string();
    const std::string common = "\"" + glint + "\" render \"" + scene + "\" -W " +
                               std::to_string(width) + " -H " + std::to_string(height) +
                               " --integrator path --max-depth " + std::to_string(max_depth) +
                               " --progress none";
    if (glint_has_variance(glint)) {
        const fs::path img = out_dir / (stem + "_glint.exr");
        const fs::path v = out_dir / (stem + "_glint.variance.exr");  // --variance's name
        run(common + " --spp " + std::to_string(spp) + " --seed 1 -o \"" + img.string() +
            "\" --variance");
        *mean = glint::io::read_linear(img.string());
        *var = glint::io::read_linear(v.string());
        return;
    }
    const int m = kSeedImages;
    const int each = std::max(1, spp / m);
    std::vector<LinearImage> images;
    for (int k = 0; k < m; ++k) {
        const fs::path img = out_dir / (stem + "_glint_seed" + std::to_string(k + 1) + ".exr");
        run(common + " --spp " + std::to_string(each) + " --seed " + std::to_string(k + 1) +
            " -o \"" + img.string() + "\"");
        images.push_back(glint::io::read_linear(img.string()));
    }
    *mean = images[0];
    *var = images[0];
    for (size_t i = 0; i < mean->rgb.size(); ++i) {
        double s = 0, s2 = 0;
        for (const LinearImage& im : images) s += im.rgb[i];
        const double mu = s / m;
        for (const LinearImage& im : images) s2 += (im.rgb[i] - mu) * (im.rgb[i] - mu);
        mean->rgb[i] = static_cast<float>(mu);
        var->rgb[i] = static_cast<float>(s2 / (m - 1) / m);
    }
    glint::io::write_linear_exr(*mean, (out_dir / (stem + "_glint.exr")).string());
}

int report(const std::string& name, const ZResult& r, const fs::path& out_dir) {
    const double fraction = static_cast<double>(r.accepted) / static_cast<double>(r.pixels);
    const bool pass = fraction >= kMinAccepted;
    std::printf("%s: accepted %lld of %lld pixels (%.4f%%, need %.2f%%), |z| threshold %.3f, "
                "worst |z| %.3g at %d,%d, relMSE %.3g: %s\n",
                name.c_str(), r.accepted, r.pixels, 100 * fraction, 100 * kMinAccepted,
                r.threshold, r.worst_z, r.worst_x, r.worst_y, r.relmse, pass ? "PASS" : "FAIL");
    if (!pass && !out_dir.empty()) {
        const fs::path z = out_dir / (name + "_z.exr");
        glint::io::write_linear_exr(r.z, z.string());
        std::printf("%s: |z| per pixel written to %s\n", name.c_str(), z.c_str());
    }
    return pass ? 0 : 1;
}

int usage() {
    std::fprintf(stderr,
                 "usage: cycles_ztest render GLINT SCENE.pov REF_MEAN.exr REF_STDERR.exr OUT_DIR "
                 "[spp] [max_depth]\n"
                 "       cycles_ztest compare GLINT.exr GLINT_VAR.exr REF_MEAN.exr REF_STDERR.exr "
                 "[OUT_DIR]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::vector<std::string> a(argv + 1, argv + argc);
        if (a.size() >= 6 && a[0] == "render") {
            const LinearImage ref = glint::io::read_linear(a[3]);
            const LinearImage se = glint::io::read_linear(a[4]);
            const fs::path out_dir = a[5];
            fs::create_directories(out_dir);
            const int spp = a.size() > 6 ? std::atoi(a[6].c_str()) : 256;
            const int depth = a.size() > 7 ? std::atoi(a[7].c_str()) : 8;
            LinearImage mean, var;
            render_glint(a[1], a[2], out_dir, ref.width, ref.height, spp, depth, &mean, &var);
            return report(fs::path(a[2]).stem().string(), z_test(mean, var, ref, se),
                          out_dir);
        }
        if (a.size() >= 5 && a[0] == "compare") {
            const LinearImage x = glint::io::read_linear(a[1]);
            const LinearImage v = glint::io::read_linear(a[2]);
            const LinearImage ref = glint::io::read_linear(a[3]);
            const LinearImage se = glint::io::read_linear(a[4]);
            return report(fs::path(a[1]).stem().string(), z_test(x, v, ref, se),
                          a.size() > 5 ? fs::path(a[5]) : fs::path());
        }
        return usage();
    } catch (const glint::Error& e) {
        std::fprintf(stderr, "cycles_ztest: %s\n", e.what());
        return 2;
    }
}
