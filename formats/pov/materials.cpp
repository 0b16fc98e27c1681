// Textures, pigments, finishes, normals, interiors and materials (reference manual 3.6
// "Textures" and 3.7 "Interior"; parstxtr.cpp in POV-Ray). Each body function reads items
// up to the closing '}' and leaves it for the caller, which reports where the block opened.
#include <cmath>
#include <filesystem>
#include <unordered_set>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

namespace fs = std::filesystem;

namespace {

// POV-Ray pattern names glint does not evaluate yet: named so the error is precise.
const std::unordered_set<std::string>& unsupported_patterns() {
    static const std::unordered_set<std::string> k = {
        "agate", "aoi", "average", "boxed", "bozo", "brick", "bumps", "cells", "crackle",
        "cylindrical", "density_file", "dents", "facets", "function", "gradient_map", "granite",
        "hexagon", "julia", "leopard", "mandel", "marble", "object", "onion", "pavement",
        "pigment_pattern", "planar", "quilted", "radial", "ripples", "slope", "spherical",
        "spiral1", "spiral2", "spotted", "square", "tiling", "triangular", "waves", "wood",
        "wrinkles", "pigment_map", "normal_map", "slope_map", "texture_map", "material_map",
        "tiles", "bump_map", "fractal", "magnet", "cubic", "noise_generator"};
    return k;
}

bool is_close(const Token& t) { return t.is_symbol('}') || t.kind == TokKind::End; }

}  // namespace

void transform_pigment(scene::Pigment& p, const Transform& t) {
    p.transform = p.transform.then(t);
    for (auto& e : p.entries) transform_pigment(e, t);
}

void transform_texture(scene::Texture& tex, const Transform& t) {
    // POV-Ray: `uv_mapping` makes the pigment a UV_MAP_PATTERN whose own warps are ignored
    // (pigment.cpp Compute_Pigment), so texture and object transforms never reach a
    // uv-mapped pigment; only the transforms inside its pigment { } apply.
    if (!tex.pigment.uv_mapping) transform_pigment(tex.pigment, t);
    tex.normal.transform = tex.normal.transform.then(t);
}

bool Parser::parse_transform_item(Transform& t) {
    const Token& k = next();
    if (k.is("translate")) {
        t = t.then(Transform::translate(parse_vector()));
    } else if (k.is("rotate")) {
        t = t.then(Transform::rotate_xyz_degrees(parse_vector()));
    } else if (k.is("scale")) {
        FileLoc l = loc();
        Vec3 s = parse_vector();
        if (s.x == 0 || s.y == 0 || s.z == 0) {
            // POV-Ray warns and replaces zero scale factors by 1 (Parse_Scale_Vector).
            diag.warning(l, "scale by zero replaced by 1");
            if (s.x == 0) s.x = 1;
            if (s.y == 0) s.y = 1;
            if (s.z == 0) s.z = 1;
        }
        t = t.then(Transform::scale(s));
    } else if (k.is("matrix")) {
        FileLoc l = loc();
        expect("<", "after 'matrix'");
        double m[12];
        for (int i = 0; i < 12; ++i) {
            if (i > 0) expect(",", "between matrix values");
            m[i] = parse_float_in_angle_brackets();
        }
        expect(">", "to close the matrix");
        try {
            t = t.then(Transform::pov_matrix(m));
        } catch (const Error&) {
            fail_at(l, "singular matrix");
        }
    } else if (k.is("transform")) {
        const Token& n = next();
        if (n.is_symbol('{')) {
            FileLoc o = loc();
            t = t.then(parse_transform_body());
            expect_close("transform", o);
        } else if (n.kind == TokKind::Word && lookup(n.text)) {
            const Symbol& s = use_symbol(n);
            auto tr = std::get_if<Transform>(&s.value);
            if (!tr) fail("expected a transform, got " + value_kind_name(s.value));
            t = t.then(*tr);
        } else {
            fail("expected '{' or a transform identifier after 'transform', got " + got(n));
        }
    } else {
        unget();
        return false;
    }
    return true;
}

Transform Parser::parse_transform_body() {
    Transform t;
    for (;;) {
        const Token& k = peek();
        if (is_close(k)) return t;
        if (k.kind == TokKind::Word && lookup(k.text)) {
            next();
            const Symbol& s = use_symbol(k);
            auto tr = std::get_if<Transform>(&s.value);
            if (!tr) fail("expected a transform, got " + value_kind_name(s.value));
            t = t.then(*tr);
            continue;
        }
        if (accept("inverse")) {
            t = t.inverse();
            continue;
        }
        if (!parse_transform_item(t))
            fail("expected translate, rotate, scale, matrix or transform, got " + got(next()));
    }
}

std::string Parser::resolve_file(const std::string& name, const FileLoc& l) const {
    if (fs::path(name).is_absolute()) {
        if (fs::is_regular_file(name)) return name;
    } else {
        std::vector<std::string> dirs = {files_[cur_file_]->dir, scene_dir_};
        for (const auto& d : options.include_dirs) dirs.push_back(d);
        for (const auto& d : dirs) {
            fs::path p = fs::path(d) / name;
            if (fs::is_regular_file(p)) return p.lexically_normal().string();
        }
    }
    throw Error(ErrorKind::MissingFile, l, "cannot find the file '" + name + "'");
}

// ---------------------------------------------------------------- pigment

static std::vector<scene::Pigment> default_checker() {
    // POV-Ray's checker without colors: blue and green (pattern.cpp, Check_Default_Map).
    scene::Pigment a, b;
    a.color = scene::ColorFT(Color(0, 0, 1));
    b.color = scene::ColorFT(Color(0, 1, 0));
    return {a, b};
}

void Parser::parse_pigment_body(scene::Pigment& p) {
    bool first = true;
    if (!p.loc.valid()) p.loc = loc();
    for (;; first = false) {
        const Token& t = next();
        if (is_close(t)) {
            unget();
            return;
        }
        if (t.kind == TokKind::Word && lookup(t.text)) {
            const Symbol& s = use_symbol(t);
            if (auto pg = std::get_if<scene::Pigment>(&s.value)) {
                if (!first) fail("a pigment identifier must come first in the pigment");
                p = *pg;
                continue;
            }
            if (!std::holds_alternative<Num>(s.value))
                fail("expected a pigment or color, got " + value_kind_name(s.value) + " '" +
                     t.text + "'");
        }
        if (t.kind == TokKind::Word && !lookup(t.text)) {
            const std::string& w = t.text;
            unget();
            Transform delta;
            if (parse_transform_item(delta)) {
                transform_pigment(p, delta);
                continue;
            }
            next();
            if (w == "checker") {
                p.kind = scene::PatternKind::Checker;
                p.params.frequency = 0;
                std::vector<scene::Pigment> e;
                for (int i = 0; i < 2; ++i) {
                    skip_comma();
                    if (accept("pigment")) {
                        expect_open("pigment");
                        FileLoc o = loc();
                        scene::Pigment sub = default_texture_.pigment;
                        sub.loc = o;
                        parse_pigment_body(sub);
                        expect_close("pigment", o);
                        e.push_back(sub);
                    } else if (next_is_expression_start()) {
                        scene::Pigment sub;
                        sub.loc = loc();
                        sub.color = parse_color();
                        e.push_back(sub);
                    } else {
                        break;
                    }
                }
                auto d = default_checker();
                while (e.size() < 2) e.push_back(d[e.size()]);
                p.entries = e;
            } else if (w == "gradient") {
                p.kind = scene::PatternKind::Gradient;
                FileLoc l = loc();
                Vec3 v = parse_vector();
                if (length(v) == 0) fail_at(l, "gradient vector has zero length");
                p.params.vector = normalize(v);  // POV-Ray normalizes it (parstxtr.cpp)
            } else if (w == "color_map" || w == "colour_map") {
                expect_open(w.c_str());
                FileLoc o = loc();
                p.color_map = parse_color_map_body();
                expect_close(w.c_str(), o);
            } else if (w == "image_map") {
                expect_open("image_map");
                FileLoc o = loc();
                p.kind = scene::PatternKind::ImageMap;
                p.params.image = scene::ImageMap{};
                p.params.image.loc = o;
                parse_image_map_body(p.params.image);
                expect_close("image_map", o);
            } else if (w == "uv_mapping") {
                p.uv_mapping = true;
            } else if (w == "quick_color" || w == "quick_colour") {
                parse_color();  // only for POV-Ray's low-quality preview
            } else if (w == "frequency") {
                p.params.frequency = parse_float();
            } else if (w == "phase") {
                p.params.phase = parse_float();
            } else if (w == "ramp_wave") {
                p.params.wave = scene::WaveType::Ramp;
            } else if (w == "triangle_wave") {
                p.params.wave = scene::WaveType::Triangle;
            } else if (w == "sine_wave") {
                p.params.wave = scene::WaveType::Sine;
            } else if (w == "scallop_wave") {
                p.params.wave = scene::WaveType::Scallop;
            } else if (w == "cubic_wave") {
                p.params.wave = scene::WaveType::Cubic;
            } else if (w == "poly_wave") {
                p.params.wave = scene::WaveType::Poly;
                p.params.wave_exponent = allow_float(1);
            } else if (w == "turbulence" || w == "octaves" || w == "omega" || w == "lambda") {
                // Check_Turb: these modify the classic turbulence warp at the front of the list.
                auto& warps = p.params.warps;
                if (warps.empty() || warps.front().kind != scene::WarpKind::ClassicTurbulence) {
                    scene::Warp t;
                    t.loc = loc();
                    warps.insert(warps.begin(), t);
                }
                scene::Turbulence& turb = warps.front().turbulence;
                if (w == "turbulence") {
                    turb.amount = parse_vector();
                } else {
                    double v = parse_float();
                    if (w == "octaves") turb.octaves = static_cast<int>(v);
                    if (w == "omega") turb.omega = v;
                    if (w == "lambda") turb.lambda = v;
                }
            } else if (unsupported_patterns().count(w)) {
                unsupported("the '" + w + "' pattern");
            } else {
                unget();
                if (!next_is_expression_start())
                    fail("expected a pigment item (color, pattern, transform, ...), got " +
                         got(next()));
                p.kind = scene::PatternKind::Plain;
                p.color = parse_color();
            }
            continue;
        }
        unget();
        if (!next_is_expression_start())
            fail("expected a pigment item (color, pattern, transform, ...), got " + got(next()));
        p.kind = scene::PatternKind::Plain;
        p.color = parse_color();
    }
}

std::vector<scene::ColorMapEntry> Parser::parse_color_map_body() {
    std::vector<scene::ColorMapEntry> map;
    for (;;) {
        const Token& t = next();
        if (is_close(t)) {
            unget();
            break;
        }
        if (!t.is_symbol('['))
            fail("expected '[' to start a color_map entry, got " + got(t));
        FileLoc o = loc();
        double v1 = parse_float();
        bool old_syntax = false;
        if (accept(",")) {
            // `[v1, v2 color c1 color c2]` (old) or `[v, color]` (a comma before the color).
            const Token& n = peek();
            old_syntax = n.kind == TokKind::Number || n.is("-") || n.is("+");
        }
        if (old_syntax) {
            // Old syntax: [v1, v2 color c1 color c2]
            double v2 = parse_float();
            scene::ColorFT c1 = parse_color();
            scene::ColorFT c2 = parse_color();
            map.push_back({v1, c1});
            map.push_back({v2, c2});
        } else {
            map.push_back({v1, parse_color()});
        }
        const Token& c = next();
        if (!c.is_symbol(']'))
            fail("expected ']' to close the color_map entry opened at " +
                 std::to_string(o.line) + ":" + std::to_string(o.column) + ", got " + got(c));
    }
    if (map.size() > 256) fail("a color_map has at most 256 entries");
    return map;
}

void Parser::parse_image_map_body(scene::ImageMap& im) {
    static const std::unordered_set<std::string> kTypes = {
        "png", "jpeg", "tga", "gif", "tiff", "ppm", "pgm", "sys", "iff", "hdr", "exr", "bmp"};
    const Token& t = next();
    if (t.kind == TokKind::Word && kTypes.count(t.text)) {
        im.type = t.text;
    } else {
        unget();
    }
    const Token& s = peek();
    if (s.kind != TokKind::String && !(s.kind == TokKind::Word && lookup(s.text)))
        fail("expected the image file name (a string), got " + got(s));
    im.file = parse_string();
    FileLoc sloc = loc();
    if (im.type.empty()) {
        std::string ext = fs::path(im.file).extension().string();
        im.type = ext.empty() ? "sys" : ext.substr(1);
    }
    im.resolved_path = resolve_file(im.file, sloc);
    for (;;) {
        const Token& k = next();
        if (is_close(k)) {
            unget();
            return;
        }
        if (k.is("map_type")) {
            im.map_type = static_cast<int>(parse_float());
            if (im.map_type != 0 && im.map_type != 1 && im.map_type != 2 && im.map_type != 5)
                fail("map_type " + std::to_string(im.map_type) + " is not supported");
        } else if (k.is("once")) {
            im.once = true;
        } else if (k.is("interpolate")) {
            im.interpolate = static_cast<int>(parse_float());
        } else if (k.is("filter") || k.is("transmit")) {
            bool filter = k.text == "filter";
            if (!accept("all")) unsupported("per-palette-index filter/transmit in image_map");
            (filter ? im.filter_all : im.transmit_all) = parse_float();
        } else if (k.is("gamma")) {
            if (accept("srgb")) {
                im.gamma = -1;  // -1 = the sRGB transfer function
            } else {
                im.gamma = parse_float();
            }
        } else if (k.is("premultiplied")) {
            im.premultiplied = allow_float(1) != 0;
        } else if (k.is("use_color") || k.is("use_colour") || k.is("use_index")) {
            // Only meaningful for paletted images; glint reads colors.
        } else {
            fail("expected an image_map item (map_type, once, interpolate, ...), got " +
                 got(k));
        }
    }
}

// ---------------------------------------------------------------- finish, normal, interior

template <class T>
bool Parser::take_body_identifier(const Token& t, bool first, const char* article,
                                  const char* noun, T& out) {
    if (t.kind != TokKind::Word || !lookup(t.text)) return false;
    const Symbol& s = use_symbol(t);
    const std::string kind = std::string(article) + " " + noun;
    auto v = std::get_if<T>(&s.value);
    if (!v)
        fail("expected " + kind + ", got " + value_kind_name(s.value) + " '" + t.text + "'");
    // POV-Ray reads the identifier only right after the brace (later items modify the copy);
    // anywhere else it is a syntax error there too.
    if (!first) fail(kind + " identifier must come first in the " + noun);
    out = *v;
    return true;
}

void Parser::parse_finish_body(scene::Finish& f) {
    bool first = true;
    if (!f.loc.valid()) f.loc = loc();
    for (;; first = false) {
        const Token& t = next();
        if (is_close(t)) {
            unget();
            return;
        }
        if (take_body_identifier(t, first, "a", "finish", f)) continue;
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        if (w == "ambient") {
            f.ambient = parse_rgb();
        } else if (w == "emission") {
            f.emission = parse_rgb();
        } else if (w == "diffuse") {
            if (accept("albedo")) unsupported("'albedo'");
            f.diffuse = parse_float();
            if (accept(",")) unsupported("diffuse backside illumination");
        } else if (w == "brilliance") {
            f.brilliance = parse_float();
        } else if (w == "phong") {
            if (accept("albedo")) unsupported("'albedo'");
            f.phong = parse_float();
        } else if (w == "phong_size") {
            f.phong_size = parse_float();
        } else if (w == "specular") {
            if (accept("albedo")) unsupported("'albedo'");
            f.specular = parse_float();
        } else if (w == "roughness") {
            f.roughness = parse_float();
        } else if (w == "metallic") {
            f.metallic = allow_float(1.0);
        } else if (w == "reflection") {
            if (accept("{")) {
                FileLoc o = loc();
                f.reflection.falloff = 1;
                f.reflection.min = parse_rgb();
                skip_comma();
                bool second = false;
                if (next_is_expression_start()) {
                    f.reflection.max = parse_rgb();
                    second = true;
                } else {
                    f.reflection.max = f.reflection.min;
                }
                for (;;) {
                    if (accept("fresnel")) {
                        f.reflection.fresnel = allow_float(1.0) != 0;
                        if (!second && f.reflection.fresnel) f.reflection.min = Color(0, 0, 0);
                    } else if (accept("falloff")) {
                        f.reflection.falloff = parse_float();
                    } else if (accept("exponent")) {
                        f.reflection.exponent = parse_float();
                    } else if (accept("metallic")) {
                        f.reflection.metallic = allow_float(1.0);
                    } else {
                        break;
                    }
                }
                expect_close("reflection", o);
            } else {
                f.reflection.max = parse_rgb();
                f.reflection.min = f.reflection.max;
                f.reflection.falloff = 1;
            }
        } else if (w == "reflection_exponent") {
            f.reflection.exponent = parse_float();
        } else if (w == "conserve_energy") {
            f.conserve_energy = allow_float(1.0) != 0;
        } else if (w == "crand") {
            f.crand = parse_float();
        } else if (w == "irid" || w == "subsurface" || w == "ior" || w == "caustics" ||
                   w == "fade_distance" || w == "fade_power" || w == "refraction") {
            unsupported("finish '" + w + "'");
        } else {
            fail("expected a finish item (ambient, diffuse, phong, ...), got " + got(t));
        }
    }
}

void Parser::parse_normal_body(scene::Normal& n) {
    bool first = true;
    if (!n.loc.valid()) n.loc = loc();
    for (;; first = false) {
        const Token& t = next();
        if (is_close(t)) {
            unget();
            return;
        }
        if (take_body_identifier(t, first, "a", "normal", n)) continue;
        unget();
        Transform tr = n.transform;
        if (parse_transform_item(tr)) {
            n.transform = tr;
            continue;
        }
        const Token& k = next();
        if (k.kind == TokKind::Word)
            unsupported("normal pattern '" + k.text + "' (normal perturbation)");
        fail("expected a normal pattern or transform, got " + got(k));
    }
}

void Parser::parse_interior_body(scene::Interior& in) {
    bool first = true;
    for (;; first = false) {
        const Token& t = next();
        if (is_close(t)) {
            unget();
            return;
        }
        if (take_body_identifier(t, first, "an", "interior", in)) continue;
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        if (w == "ior") in.ior = parse_float();
        else if (w == "dispersion") in.dispersion = parse_float();
        else if (w == "dispersion_samples") parse_float();
        else if (w == "caustics") in.caustics = parse_float();
        else if (w == "fade_distance") in.fade_distance = parse_float();
        else if (w == "fade_power") in.fade_power = parse_float();
        else if (w == "fade_color" || w == "fade_colour") in.fade_color = parse_rgb();
        else if (w == "media") {
            warn_unsupported(*this, "media", loc(), "media and its density are ignored");
            skip_braced_block(*this, w);
        }
        else fail("expected an interior item (ior, fade_distance, ...), got " + got(t));
    }
}

// ---------------------------------------------------------------- texture, material

scene::Texture Parser::parse_texture_body() {
    scene::Texture tex = default_texture_;
    tex.loc = loc();
    bool first = true;
    for (;; first = false) {
        const Token& t = next();
        if (is_close(t)) {
            unget();
            return tex;
        }
        if (take_body_identifier(t, first, "a", "texture", tex)) continue;
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        if (w == "pigment") {
            expect_open("pigment");
            FileLoc o = loc();
            parse_pigment_body(tex.pigment);
            expect_close("pigment", o);
        } else if (w == "normal") {
            expect_open("normal");
            FileLoc o = loc();
            parse_normal_body(tex.normal);
            expect_close("normal", o);
        } else if (w == "finish") {
            expect_open("finish");
            FileLoc o = loc();
            parse_finish_body(tex.finish);
            expect_close("finish", o);
        } else if (unsupported_patterns().count(w) || w == "checker" || w == "gradient" ||
                   w == "image_map" || w == "hexagon" || w == "brick") {
            unsupported("a patterned texture ('" + w + "' in a texture)");
        } else {
            unget();
            Transform tr;
            if (!parse_transform_item(tr))
                fail("expected a texture item (pigment, normal, finish, transform), got " +
                     got(next()));
            transform_texture(tex, tr);
        }
    }
}

MaterialValue Parser::parse_material_body() {
    MaterialValue m;
    bool first = true;
    for (;; first = false) {
        const Token& t = next();
        if (is_close(t)) {
            unget();
            return m;
        }
        if (t.kind == TokKind::Word && lookup(t.text)) {
            const Symbol& s = use_symbol(t);
            auto mv = std::get_if<MaterialValue>(&s.value);
            if (!mv || !first) fail("expected a material, got " + value_kind_name(s.value));
            m = *mv;
            continue;
        }
        if (t.is("texture")) {
            expect_open("texture");
            FileLoc o = loc();
            m.texture = parse_texture_body();
            expect_close("texture", o);
        } else if (t.is("interior")) {
            expect_open("interior");
            FileLoc o = loc();
            scene::Interior in = m.interior.value_or(scene::Interior{});
            parse_interior_body(in);
            m.interior = in;
            expect_close("interior", o);
        } else {
            unget();
            Transform tr;
            if (!parse_transform_item(tr))
                fail("expected texture, interior or a transform in the material, got " +
                     got(next()));
            if (m.texture) transform_texture(*m.texture, tr);
        }
    }
}

}  // namespace glint::pov
