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

bool is_close(const Token& t) { return t.is_symbol('}') || t.kind == TokKind::End; }

}  // namespace

void transform_pigment(scene::Pigment& p, const Transform& t) {
    // Map and block entries live in the parent's pattern space: they move with it.
    p.transform = p.transform.then(t);
}

void transform_texture(scene::Texture& tex, const Transform& t) {
    // Transform_Textures: a patterned texture moves its pattern (its entries follow); a plain
    // one its pigment and normal, in every layer.
    if (tex.kind != scene::PatternKind::Plain) {
        tex.transform = tex.transform.then(t);
        return;
    }
    // POV-Ray: `uv_mapping` makes the pigment a UV_MAP_PATTERN whose own warps are ignored
    // (pigment.cpp Compute_Pigment), so texture and object transforms never reach a
    // uv-mapped pigment; only the transforms inside its pigment { } apply.
    if (!tex.pigment.uv_mapping) transform_pigment(tex.pigment, t);
    if (!tex.normal.uv_mapping) tex.normal.transform = tex.normal.transform.then(t);
    for (auto& l : tex.layers) transform_texture(l, t);
}

bool texture_is_uniform(const scene::Texture& tex) {
    if (tex.kind != scene::PatternKind::Plain || tex.pigment.kind != scene::PatternKind::Plain ||
        tex.normal.kind != scene::PatternKind::Plain)
        return false;
    for (const scene::Texture& l : tex.layers)
        if (!texture_is_uniform(l)) return false;
    return true;
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

// ---------------------------------------------------------------- pigment

void Parser::parse_image_map_body(scene::ImageMap& im, double* bump_size, bool material_map,
                                  bool image_pattern) {
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
        // A material_map's image items end where its textures begin.
        if (is_close(k) || (material_map && k.is("texture"))) {
            unget();
            return;
        }
        if (bump_size && k.is("bump_size")) {
            *bump_size = parse_float();
        } else if (k.is("map_type")) {
            im.map_type = to_int(parse_float());
            if (im.map_type != 0 && im.map_type != 1 && im.map_type != 2 && im.map_type != 5)
                fail("map_type " + std::to_string(im.map_type) + " is not supported");
        } else if (k.is("once")) {
            im.once = true;
        } else if (k.is("interpolate")) {
            im.interpolate = to_int(parse_float());
        } else if (k.is("filter") || k.is("transmit")) {
            bool filter = k.text == "filter";
            scene::ImageMap::PaletteEdit edit;
            edit.filter = filter;
            edit.loc = loc();
            if (!accept("all")) {
                // filter/transmit N, V: entry N of the image's palette. Whether the image has
                // a palette (and N entries) is checked where the image is read.
                double n = parse_float();
                if (n + 0.01 < 0)
                    fail(std::string(filter ? "filter" : "transmit") +
                         " colour register value out of range");
                edit.index = static_cast<int>(n + 0.01);
                skip_comma();
                edit.value = parse_float();
            } else {
                edit.value = parse_float();
                (filter ? im.filter_all : im.transmit_all) = edit.value;
            }
            im.palette_edits.push_back(edit);
        } else if (k.is("gamma")) {
            if (accept("srgb")) {
                im.gamma = -1;  // -1 = the sRGB transfer function
            } else {
                im.gamma = parse_float();
            }
        } else if (k.is("premultiplied")) {
            im.premultiplied = allow_float(1) != 0;
        } else if (k.is("use_color") || k.is("use_colour") || k.is("use_index")) {
            // Only a bump_map on a palette image tells them apart (image_pattern reads the
            // grey with either: its test in imageutil.cpp holds for both).
            im.use_index = k.is("use_index");
            im.use_alpha = false;
        } else if (image_pattern && k.is("use_alpha")) {
            im.use_alpha = true;
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

// patterns.cpp reads normal and texture identifiers with it too.
template bool Parser::take_body_identifier(const Token&, bool, const char*, const char*,
                                           scene::Normal&);
template bool Parser::take_body_identifier(const Token&, bool, const char*, const char*,
                                           scene::Texture&);
template bool Parser::take_body_identifier(const Token&, bool, const char*, const char*,
                                           scene::Media&);

void Parser::parse_finish_body(scene::Finish& f, bool one_item) {
    bool first = true;
    if (!f.loc.valid()) f.loc = loc();
    for (int items = 0; !one_item || items < 1; first = false, ++items) {
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
            if (accept("albedo")) warn_unsupported(*this, "albedo", loc(), "ignored");
            f.diffuse = parse_float();
            if (accept(",")) f.diffuse_back = parse_float();
        } else if (w == "brilliance") {
            f.brilliance = parse_float();
        } else if (w == "phong") {
            if (accept("albedo")) warn_unsupported(*this, "albedo", loc(), "ignored");
            f.phong = parse_float();
        } else if (w == "phong_size") {
            f.phong_size = parse_float();
        } else if (w == "specular") {
            if (accept("albedo")) warn_unsupported(*this, "albedo", loc(), "ignored");
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
        } else if (w == "subsurface") {
            expect_open("subsurface");
            FileLoc o = loc();
            f.subsurface = true;
            for (;;) {
                if (accept("translucency")) {
                    f.translucency = parse_rgb();
                } else if (accept("anisotropy")) {
                    parse_rgb();  // (parsed by POV-Ray 3.7, and unused by it too)
                } else {
                    break;
                }
            }
            expect_close("subsurface", o);
        } else if (w == "irid") {  // irid { amount [thickness t] [turbulence u] }
            expect_open("irid");
            FileLoc o = loc();
            f.irid = parse_float();
            for (;;) {
                if (accept("thickness")) f.irid_thickness = parse_float();
                else if (accept("turbulence")) f.irid_turbulence = parse_vector().x;
                else break;
            }
            expect_close("irid", o);
        } else if (w == "ior" || w == "caustics" || w == "refraction") {
            // POV-Ray 3.0's interior items inside finish: the object's interior takes them
            // (Parser::add_material), as POV-Ray 3.7 still does, with its warning.
            const FileLoc at = loc();
            const double v = parse_float();
            if (w == "ior") f.old_ior = v;
            else if (w == "caustics") f.old_caustics = v;
            else f.old_refraction = v;
            diag.warning(at, "finish " + w + " is POV-Ray 3.0 syntax: write it in interior { }" +
                                 (w == "refraction" ? " (as fade_distance and fade_power)" : ""));
        } else if (w == "fade_distance" || w == "fade_power") {
            warn_unsupported(*this, "finish " + w, loc(), "ignored (write it in interior)");
            parse_float();
        } else {
            fail("expected a finish item (ambient, diffuse, phong, ...), got " + got(t));
        }
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
            expect_open("media");
            FileLoc o = loc();
            scene::Media m = new_media();
            parse_media_body(m);
            expect_close("media", o);
            in.media.push_back(std::move(m));
        }
        else fail("expected an interior item (ior, fade_distance, ...), got " + got(t));
    }
}

// ---------------------------------------------------------------- texture, material

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
        } else if (t.is("interior_texture")) {
            expect_open("interior_texture");
            FileLoc o = loc();
            m.interior_texture = parse_texture_body();
            expect_close("interior_texture", o);
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
            if (m.interior_texture) transform_texture(*m.interior_texture, tr);
        }
    }
}

}  // namespace glint::pov
