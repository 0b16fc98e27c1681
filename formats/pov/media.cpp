// media { } and density { } (reference manual 3.4.4.2 / 3.5.7; parstxtr.cpp Parse_Media and
// Parse_Media_Density_Pattern). Values are stored as POV-Ray stores them after parsing.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

void transform_media(scene::Media& m, const Transform& t) {
    for (scene::Pigment& d : m.density) transform_pigment(d, t);
}

void transform_interior(scene::Interior& in, const Transform& t) {
    for (scene::Media& m : in.media) transform_media(m, t);
}

// After `density {`: a pigment body in which `density_map` (entries are density bodies or
// colours) takes the place of color_map/pigment_map.
scene::Pigment Parser::parse_density_body() {
    scene::Pigment d;
    d.loc = loc();
    const bool outer = in_density_;
    in_density_ = true;
    parse_pigment_body(d);
    in_density_ = outer;
    return d;
}

std::shared_ptr<const scene::DensityGrid> Parser::load_df3(const std::string& name,
                                                           const std::string& path,
                                                           const FileLoc& at) {
    if (auto it = df3_cache_.find(path); it != df3_cache_.end()) return it->second;
    // Read_Density_File: three big-endian 16-bit sizes, then the voxels, x fastest, at 8, 16
    // or 32 bits each (whichever the file's length fits), big-endian.
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) fail_at(at, "cannot read the density file '" + name + "'");
    // (At 4 bytes per float, a 256 MiB file makes a grid of up to 1 GiB.)
    if (size > (size_t{256} << 20))
        fail_at(at, "the density file '" + name + "' is over 256 MiB (" + std::to_string(size) +
                        " bytes)");
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) fail_at(at, "cannot read the density file '" + name + "'");
    if (bytes.size() < 6) fail_at(at, "'" + name + "' is not a df3 density file (too short)");
    auto u16 = [&](size_t i) { return static_cast<int>(bytes[i]) << 8 | bytes[i + 1]; };
    auto grid = std::make_shared<scene::DensityGrid>();
    grid->nx = u16(0);
    grid->ny = u16(2);
    grid->nz = u16(4);
    grid->path = path;
    const size_t count = static_cast<size_t>(grid->nx) * grid->ny * grid->nz;
    const size_t len = bytes.size() - 6;
    if (count == 0 || len % count != 0 || (len / count != 1 && len / count != 2 && len / count != 4))
        fail_at(at, "'" + name + "' is not a df3 density file: " + std::to_string(grid->nx) +
                        " x " + std::to_string(grid->ny) + " x " + std::to_string(grid->nz) +
                        " voxels do not fill its " + std::to_string(len) + " bytes of data");
    const size_t width = len / count;
    grid->values.resize(count);
    const double scale = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0;
    for (size_t i = 0; i < count; ++i) {
        uint64_t v = 0;
        for (size_t b = 0; b < width; ++b) v = v << 8 | bytes[6 + i * width + b];
        grid->values[i] = static_cast<float>(static_cast<double>(v) / scale);
    }
    df3_cache_[path] = grid;
    return grid;
}

scene::Media Parser::new_media() const {
    scene::Media m;
    // Parse_Media: before #version 3.5 the default sampling was method 1 with 10 intervals
    // of one sample each.
    if (version() < 3.5) {
        m.method = 1;
        m.intervals = 10;
        m.min_samples = 1;
        m.max_samples = 1;
    }
    return m;
}

void Parser::parse_media_body(scene::Media& m) {
    if (!m.loc.valid()) m.loc = loc();
    bool first = true;
    for (;; first = false) {
        const Token& t = next();
        if (t.is_symbol('}') || t.kind == TokKind::End) {
            // Every ray through the medium takes this many samples, at least: a bound against
            // a scene that would never finish (POV-Ray's own examples take at most 400).
            const long long work = static_cast<long long>(m.intervals) *
                                   std::max(m.min_samples, m.max_samples);
            if (work > 100000)
                fail_at(m.loc, "media sampling of " + std::to_string(m.intervals) +
                                   " intervals x " + std::to_string(m.max_samples) +
                                   " samples is over the limit of 100000 samples per ray");
            unget();
            return;
        }
        if (take_body_identifier(t, first, "a", "media", m)) continue;
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        FileLoc at = loc();
        if (w == "intervals") {
            double v = parse_float();
            if (!(v >= 1)) fail_at(at, "at least one interval is needed in media");
            if (v > 10000) fail_at(at, "media intervals are limited to 10000");
            m.intervals = static_cast<int>(v);
        } else if (w == "samples") {
            double lo = parse_float();
            skip_comma();
            double hi = allow_float(lo);
            if (!(lo >= 1)) fail_at(at, "at least one sample per interval is needed in media");
            if (!(lo <= 10000 && hi <= 10000))
                fail_at(at, "media samples are limited to 10000 per interval");
            if (!(hi >= static_cast<int>(lo)))
                fail_at(at, "the maximum number of media samples is smaller than the minimum");
            m.min_samples = static_cast<int>(lo);
            m.max_samples = static_cast<int>(hi);
        } else if (w == "method") {
            double v = parse_float();
            if (v != 1 && v != 2 && v != 3) fail_at(at, "media method choices are 1, 2 or 3");
            m.method = static_cast<int>(v);
        } else if (w == "jitter") {
            m.jitter = parse_float();
        } else if (w == "aa_threshold") {
            m.aa_threshold = parse_float();
            if (!(m.aa_threshold > 0)) fail_at(at, "aa_threshold in media must be greater than 0");
        } else if (w == "aa_level") {
            double v = parse_float();
            if (!(v >= 1)) fail_at(at, "aa_level in media must be at least 1");
            if (v > 16) fail_at(at, "aa_level in media is limited to 16");
            m.aa_level = static_cast<int>(v);
        } else if (w == "collect") {
            m.collect = allow_float(1.0) > 0.0;
        } else if (w == "absorption") {
            m.absorption = parse_rgb();
        } else if (w == "emission") {
            m.emission = parse_rgb();
        } else if (w == "scattering") {
            expect_open("scattering");
            FileLoc o = loc();
            double type = parse_float();
            if (type < 1 || type > 5 || type != std::floor(type))
                diag.warning(o, "unknown media scattering type (1 to 5); isotropic is used");
            else
                m.type = static_cast<scene::ScatteringType>(static_cast<int>(type));
            skip_comma();
            m.scattering = parse_rgb();
            for (;;) {
                if (accept("eccentricity")) {
                    if (m.type != scene::ScatteringType::HenyeyGreenstein)
                        fail("eccentricity can only be used with scattering type 5");
                    m.eccentricity = parse_float();
                } else if (accept("extinction")) {
                    m.extinction = parse_float();
                } else {
                    break;
                }
            }
            expect_close("scattering", o);
        } else if (w == "confidence") {
            m.confidence = parse_float();
            if (!(m.confidence >= 0 && m.confidence < 1))
                fail_at(at, "media confidence must be at least 0 and below 1");
        } else if (w == "variance") {
            m.variance = parse_float();
        } else if (w == "ratio") {
            m.ratio = parse_float();
        } else if (w == "density") {
            expect_open("density");
            FileLoc o = loc();
            m.density.push_back(parse_density_body());
            expect_close("density", o);
        } else {
            unget();
            Transform delta;
            if (!parse_transform_item(delta))
                fail("expected a media item (absorption, emission, scattering, density, "
                     "samples, ...), got " + got(next()));
            transform_media(m, delta);
        }
    }
}

}  // namespace glint::pov
