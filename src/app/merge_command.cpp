// `glint merge PART... -o OUT`: the regions of one render (glint render --region) joined into
// the whole image, their pixels copied as stored (no decoding or encoding: the result is the
// single-process render bit for bit). Refuses parts of other jobs or sizes, overlapping parts
// and gaps, naming them. `--verify PART...` checks parts (the frames of an animation) without
// writing anything.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/parts.h"
#include "core/error.h"
#include "image/image_library.h"
#include "io/image_output.h"

namespace glint::app {

CLI::App* add_merge_command(CLI::App& app, MergeArgs& args) {
    CLI::App* cmd =
        app.add_subcommand("merge", "Join the parts of a render into the whole image, bit for bit");
    cmd->footer(
        "Join the parts of a render (glint render --region, written by glint farm) into the "
        "whole image, bit for bit; refuses parts of other jobs or image sizes, overlaps and gaps");
    cmd->add_option("parts", args.parts, "The parts: PNG, TIFF or EXR files of one job")
        ->required();
    cmd->add_option("-o,--output", args.output, "The whole image, in the parts' format");
    cmd->add_flag("--verify", args.verify,
                  "Only check that every part reads back in full and that they belong to one "
                  "job (the frames of an animation); write nothing");
    return cmd;
}

namespace {

Error merge_error(const std::string& message) { return Error(ErrorKind::Usage, {}, message); }

std::string text_of(const ImageHeader& h, const char* key) {
    for (const auto& [k, v] : h.text)
        if (k == key) return v;
    return {};
}

struct Part {
    std::string path;
    ImageHeader header;
    std::vector<float> pixels;  // header.channels per pixel, as ImageReader gives them
    std::string job, frame;
    render::Region region;      // in the whole image
    int width = 0, height = 0;  // of the whole image
};

// Reads a part in full; anything missing or unreadable is an error naming the file.
Part read_part(const std::string& path, bool need_region) {
    Part p;
    p.path = path;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw Error(ErrorKind::MissingFile, {}, "part " + path + " is missing");
    if (std::filesystem::is_directory(path, ec))
        throw Error(ErrorKind::MissingFile, {}, "part " + path + " is a folder, not an image");
    std::string error;
    // As stored: no premultiplying of a PNG's straight alpha on the way in.
    auto reader = image_library().open(path, {{"oiio:UnassociatedAlpha", 1}}, &error);
    if (!reader) throw Error(ErrorKind::MissingFile, {}, "cannot read part " + path + ": " + error);
    p.header = reader->header();
    const ImageHeader& h = p.header;
    p.pixels.resize(static_cast<size_t>(h.width) * h.height * h.channels);
    error = reader->read(h.channels, p.pixels.data());
    if (!error.empty())
        throw Error(ErrorKind::MissingFile, {}, "part " + path + " is incomplete: " + error);
    p.job = text_of(h, kJobKey);
    p.frame = text_of(h, kFrameKey);
    if (p.job.empty())
        throw merge_error("part " + path + " has no glint job signature (" + kJobKey +
                          "): not written by glint render");
    const std::string size = text_of(h, kSizeKey);
    if (std::sscanf(size.c_str(), "%dx%d", &p.width, &p.height) != 2)
        throw merge_error("part " + path + " does not say the size of its image (" + kSizeKey + ")");
    const std::string region = text_of(h, kRegionKey);
    if (region.empty()) {
        if (need_region)
            throw merge_error("part " + path + " is a whole image, not a region (" + kRegionKey + ")");
        p.region = {0, 0, p.width, p.height};
    } else {
        p.region = parse_region(region, std::string("part ") + path + ": " + kRegionKey);
    }
    if (p.region.width() != h.width || p.region.height() != h.height || p.region.x1 > p.width ||
        p.region.y1 > p.height)
        throw merge_error("part " + path + " is " + std::to_string(h.width) + "x" +
                          std::to_string(h.height) + " pixels but says it is region " +
                          region_string(p.region) + " of a " + size + " image");
    return p;
}

void check_same_job(const std::vector<Part>& parts) {
    const Part& a = parts.front();
    for (const Part& b : parts) {
        if (b.width != a.width || b.height != a.height)
            throw merge_error("parts of different image sizes: " + a.path + " (" +
                              std::to_string(a.width) + "x" + std::to_string(a.height) + ") and " +
                              b.path + " (" + std::to_string(b.width) + "x" +
                              std::to_string(b.height) + ")");
        if (b.job != a.job)
            throw merge_error("parts of different jobs: " + a.path + " (job " + a.job + ") and " +
                              b.path + " (job " + b.job + "): another scene or other settings");
        if (b.header.channels != a.header.channels || b.header.type != a.header.type ||
            b.header.format != a.header.format)
            throw merge_error("parts stored differently (format, channels or pixel type): " +
                              a.path + " and " + b.path);
    }
}

// The first pixel no part covers, row by row, or false when every pixel is covered.
bool first_gap(const std::vector<Part>& parts, int width, int height, int* gx, int* gy) {
    std::vector<std::pair<int, int>> spans;
    for (int y = 0; y < height; ++y) {
        spans.clear();
        for (const Part& p : parts)
            if (y >= p.region.y0 && y < p.region.y1) spans.emplace_back(p.region.x0, p.region.x1);
        std::sort(spans.begin(), spans.end());
        int x = 0;
        for (const auto& [a, b] : spans) {
            if (a > x) break;
            x = std::max(x, b);
        }
        if (x < width) {
            *gx = x;
            *gy = y;
            return true;
        }
    }
    return false;
}

// A float ImageReader value back to the integer it was read from (exact: v / max in float is
// within a millionth of the code).
template <class T>
T code_of(float v, double max) {
    return static_cast<T>(std::lround(std::clamp(static_cast<double>(v), 0.0, 1.0) * max));
}

}  // namespace

int run_merge(const MergeArgs& args) {
    if (args.verify) {
        std::vector<Part> parts;
        for (const std::string& path : args.parts) parts.push_back(read_part(path, false));
        check_same_job(parts);
        std::map<std::string, std::string> frames;
        for (const Part& p : parts) {
            auto [it, fresh] = frames.emplace(p.frame + "@" + region_string(p.region), p.path);
            if (!fresh) throw merge_error("parts " + it->second + " and " + p.path + " are the same frame and region");
        }
        std::printf("%zu parts of job %s: complete\n", parts.size(), parts.front().job.c_str());
        return kExitOk;
    }
    if (args.output.empty()) throw merge_error("no output: give -o OUT");
    std::vector<Part> parts;
    for (const std::string& path : args.parts) parts.push_back(read_part(path, true));
    check_same_job(parts);
    const Part& first = parts.front();
    const int width = first.width, height = first.height;
    namespace fs = std::filesystem;
    auto ext = [](const std::string& p) {
        std::string e = fs::path(p).extension().string();
        std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
        return e == ".tiff" ? std::string(".tif") : e;
    };
    if (ext(args.output) != ext(first.path))
        throw merge_error("-o " + args.output + ": the parts are " + ext(first.path) +
                          " files, and merge writes their pixels as they are stored");
    if (first.header.format == "jpeg" || first.header.format == "hdr")
        throw merge_error(first.path + ": " + first.header.format +
                          " parts cannot be joined bit for bit (use PNG, TIFF or EXR)");
    for (size_t i = 0; i < parts.size(); ++i)
        for (size_t j = i + 1; j < parts.size(); ++j) {
            const render::Region &a = parts[i].region, &b = parts[j].region;
            const int x0 = std::max(a.x0, b.x0), x1 = std::min(a.x1, b.x1);
            const int y0 = std::max(a.y0, b.y0), y1 = std::min(a.y1, b.y1);
            if (x0 < x1 && y0 < y1)
                throw merge_error("parts " + parts[i].path + " and " + parts[j].path +
                                  " overlap in " + region_string({x0, y0, x1, y1}));
        }
    int gx = 0, gy = 0;
    if (first_gap(parts, width, height, &gx, &gy))
        throw merge_error("the parts do not cover the " + std::to_string(width) + "x" +
                          std::to_string(height) + " image: pixel " + std::to_string(gx) + "," +
                          std::to_string(gy) + " is in none of them (a part is missing)");

    const int channels = first.header.channels;
    const size_t values = static_cast<size_t>(width) * height * channels;
    std::vector<float> f32;
    std::vector<uint8_t> u8;
    std::vector<uint16_t> u16;
    const PixelType type = first.header.type;
    if (type == PixelType::UInt8) u8.resize(values);
    else if (type == PixelType::UInt16) u16.resize(values);
    else f32.resize(values);
    for (const Part& p : parts) {
        const render::Region& r = p.region;
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x)
                for (int c = 0; c < channels; ++c) {
                    const float v =
                        p.pixels[(static_cast<size_t>(y - r.y0) * r.width() + (x - r.x0)) * channels + c];
                    const size_t at = (static_cast<size_t>(y) * width + x) * channels + c;
                    if (type == PixelType::UInt8) u8[at] = code_of<uint8_t>(v, 255);
                    else if (type == PixelType::UInt16) u16[at] = code_of<uint16_t>(v, 65535);
                    else f32[at] = v;
                }
    }
    ImageWrite w;
    w.format = first.header.format;
    w.width = width;
    w.height = height;
    w.channels = channels;
    w.alpha_channel = first.header.alpha_channel;
    w.type = type == PixelType::UInt8 || type == PixelType::UInt16 ? type : PixelType::Float;
    w.data = type == PixelType::UInt8    ? static_cast<const void*>(u8.data())
             : type == PixelType::UInt16 ? static_cast<const void*>(u16.data())
                                         : static_cast<const void*>(f32.data());
    if (!first.header.colorspace.empty())
        w.attributes.emplace_back("oiio:ColorSpace", first.header.colorspace);
    if (first.header.gamma > 0) w.attributes.emplace_back("oiio:Gamma", first.header.gamma);
    if (w.alpha_channel >= 0 && type == PixelType::UInt8)
        w.attributes.emplace_back("oiio:UnassociatedAlpha", 1);
    io::ImageMetadata metadata;
    for (const auto& [k, v] : first.header.text)
        if (k != kRegionKey && k.rfind("oiio:", 0) != 0) metadata.emplace_back(k, v);
    metadata.emplace_back("glint:merged", std::to_string(parts.size()) + " parts");
    io::write_pixels(args.output, std::move(w), metadata);
    std::printf("merged %zu parts of job %s into %s (%dx%d)\n", parts.size(), first.job.c_str(),
                args.output.c_str(), width, height);
    return kExitOk;
}

}  // namespace glint::app
