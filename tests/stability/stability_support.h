// Shared helpers of the stability suite (VALIDATION.md's extreme cases): load a scene from
// tests/stability/scenes with a few #declare'd parameters in front, render it through the
// library into the linear float film, and measure images (8-bit encoding, finite values,
// primary rays as the camera contract in scene/camera.h defines them).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/log.h"
#include "formats/pov/parser.h"
#include "io/image_compare.h"
#include "render/render.h"
#include "scene/scene.h"

namespace glint::stability {

inline std::string scenes_dir() {
    return std::string(GLINT_SOURCE_DIR) + "/tests/stability/scenes";
}

// Parses `#declare`s given in `prelude`, then #includes scenes_dir()/file, so that one scene
// file serves every parameter value the test needs.
inline scene::Scene load_scene(const std::string& file, const std::string& prelude, int width,
                               int height) {
    pov::ParseOptions options;
    options.include_dirs = {scenes_dir()};
    options.image_width = width;
    options.image_height = height;
    Diagnostics diag;
    const std::string text = prelude + "\n#include \"" + file + "\"\n";
    return pov::parse_string(text, scenes_dir() + "/prelude_" + file, options, diag);
}

inline Image render_scene(const scene::Scene& scene, int width, int height, int threads = 0,
                                  render::AaMode aa = render::AaMode::None) {
    render::RenderOptions options;
    options.width = width;
    options.height = height;
    options.aa = aa;
    options.threads = threads;
    Diagnostics diag;
    return render::render(scene, options, diag).image;
}

// The path tracer with a fixed seed: `threads` 0 uses every hardware thread.
inline render::RenderResult render_path_tracer(const scene::Scene& scene, int width, int height,
                                               int spp, int max_depth = 8, uint32_t seed = 1,
                                               int threads = 0) {
    render::RenderOptions options;
    options.width = width;
    options.height = height;
    options.integrator = render::IntegratorKind::Path;
    options.spp = spp;
    options.max_depth = max_depth;
    options.seed = seed;
    options.threads = threads;
    Diagnostics diag;
    return render::render(scene, options, diag);
}

inline Image render_file(const std::string& file, const std::string& prelude, int width,
                                 int height, int threads = 0) {
    return render_scene(load_scene(file, prelude, width, height), width, height, threads);
}

// 8-bit output value of a linear film value: gamma 2.2, POV-Ray's default File_Gamma for
// scenes with assumed_gamma 1.0 (reference manual 3.2.8.5 "File_Gamma").
inline int to_8bit(float linear) {
    const double v = std::clamp(static_cast<double>(linear), 0.0, 1.0);
    return static_cast<int>(std::lround(std::pow(v, 1.0 / 2.2) * 255.0));
}

// Largest 8-bit channel difference at pixel (x, y).
inline int diff_8bit(const Image& a, const Image& b, int x, int y) {
    int d = 0;
    for (int c = 0; c < 3; ++c)
        d = std::max(d, std::abs(to_8bit(a.pixel(x, y)[c]) - to_8bit(b.pixel(x, y)[c])));
    return d;
}

// Number of film values (floats) that differ bit for bit; different sizes count as all.
inline long differing_values(const Image& a, const Image& b) {
    if (a.rgba.size() != b.rgba.size())
        return static_cast<long>(std::max(a.rgba.size(), b.rgba.size()));
    long n = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i)
        if (std::memcmp(&a.rgba[i], &b.rgba[i], sizeof(float)) != 0) ++n;
    return n;
}

// Fraction of pixels whose largest 8-bit channel difference is <= tolerance.
inline double fraction_within(const Image& a, const Image& b, int tolerance) {
    long within = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (diff_8bit(a, b, x, y) <= tolerance) ++within;
    return static_cast<double>(within) / (static_cast<double>(a.width) * a.height);
}

inline long count_nonfinite(const Image& image) {
    return std::count_if(image.rgba.begin(), image.rgba.end(),
                         [](float v) { return !std::isfinite(v); });
}

// The primary ray through the centre of pixel (x, y), per the contract in scene/camera.h.
struct CameraRay {
    Vec3 origin;
    Vec3 dir;  // normalized
};
inline CameraRay primary_ray(const scene::Camera& cam, int x, int y, int width, int height) {
    const double sx = (x + 0.5) / width - 0.5;
    const double sy = 0.5 - (y + 0.5) / height;
    if (cam.kind == scene::CameraKind::Orthographic)
        return {cam.location + cam.right * sx + cam.up * sy, normalize(cam.direction)};
    return {cam.location, normalize(cam.direction + cam.right * sx + cam.up * sy)};
}

// POV-Ray 3.7 as the peer for the cases where its absolute epsilons fail (VALIDATION.md):
// renders `prelude` + scenes_dir()/file in a fresh folder under /tmp (POV-Ray writes only there
// and under its working directory) with VALIDATION.md's reference command, one ray per pixel
// centre, and returns its PNG as linear film values (inverse of to_8bit, so that to_8bit gives
// back POV-Ray's 8-bit values). Empty when `povray` is not installed or fails.
inline bool povray_available() { return std::system("command -v povray >/dev/null 2>&1") == 0; }
inline std::optional<Image> povray_render(const std::string& file,
                                                  const std::string& prelude, int width,
                                                  int height) {
    if (!povray_available()) return std::nullopt;
    char dir_template[] = "/tmp/glint_stability_XXXXXX";
    const char* dir = mkdtemp(dir_template);
    if (!dir) return std::nullopt;
    const std::string folder = dir;
    std::ofstream(folder + "/scene.pov") << prelude << "\n#include \"" << file << "\"\n";
    const std::string command = "cd " + folder + " && povray +Iscene.pov +Oout.png +W" +
                                std::to_string(width) + " +H" + std::to_string(height) +
                                " -D -A +WT1 -GA +L" + scenes_dir() +
                                " +L/usr/share/povray-3.7/include >log.txt 2>&1";
    std::optional<Image> result;
    if (std::system(command.c_str()) == 0) {
        try {
            const io::Rgb8Image png = io::read_rgb8(folder + "/out.png");
            Image image;
            image.width = png.width;
            image.height = png.height;
            image.rgba.assign(static_cast<size_t>(png.width) * png.height * 4, 1.0f);
            for (size_t i = 0; i < static_cast<size_t>(png.width) * png.height; ++i)
                for (int c = 0; c < 3; ++c)
                    image.rgba[i * 4 + c] =
                        static_cast<float>(std::pow(png.rgb[i * 3 + c] / 255.0, 2.2));
            result = std::move(image);
        } catch (const std::exception&) {
        }
    }
    if (std::system(("rm -rf " + folder).c_str()) != 0) std::fprintf(stderr, "rm %s failed\n", dir);
    return result;
}

}  // namespace glint::stability
