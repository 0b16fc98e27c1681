// media { } and density { } (reference manual 3.4.4.2 / 3.5.7; parstxtr.cpp Parse_Media and
// Parse_Media_Density_Pattern). Values are stored as POV-Ray stores them after parsing.
#include <cmath>

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
            if (!(hi >= static_cast<int>(lo)))
                fail_at(at, "the maximum number of media samples is smaller than the minimum");
            if (hi > 10000) fail_at(at, "media samples are limited to 10000 per interval");
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
