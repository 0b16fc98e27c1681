// Patterned pigments, normals and textures (reference manual 3.4.11 "Patterns", 3.4.6 "Texture
// maps"; parstxtr.cpp and express.cpp Parse_Blend_List in POV-Ray 3.7): the pigment, normal and
// texture bodies, the pattern keywords that open them, and the entry lists of block patterns.
// Each body function reads items up to the closing '}' (or ']' inside a map entry) and leaves it
// for the caller. The arguments and modifiers every pattern shares, warps and the maps are in
// pattern_grammar.cpp.
#include <cmath>
#include <optional>
#include <unordered_set>

#include "formats/pov/parser_impl.h"
#include "formats/pov/unsupported.h"

namespace glint::pov {

namespace {

using scene::PatternKind;

bool is_body_end(const Token& t) {
    return t.is_symbol('}') || t.is_symbol(']') || t.kind == TokKind::End;
}

struct PatternWord {
    const char* name;
    PatternKind kind;
};

constexpr PatternWord kPatternWords[] = {
    {"agate", PatternKind::Agate},         {"boxed", PatternKind::Boxed},
    {"bozo", PatternKind::Bozo},           {"bumps", PatternKind::Bumps},
    {"cells", PatternKind::Cells},         {"crackle", PatternKind::Crackle},
    {"cylindrical", PatternKind::Cylindrical}, {"dents", PatternKind::Dents},
    {"facets", PatternKind::Facets},       {"granite", PatternKind::Granite},
    {"leopard", PatternKind::Leopard},     {"marble", PatternKind::Marble},
    {"onion", PatternKind::Onion},         {"planar", PatternKind::Planar},
    {"quilted", PatternKind::Quilted},     {"radial", PatternKind::Radial},
    {"ripples", PatternKind::Ripples},     {"spherical", PatternKind::Spherical},
    {"spiral1", PatternKind::Spiral1},     {"spiral2", PatternKind::Spiral2},
    {"spotted", PatternKind::Spotted},     {"waves", PatternKind::Waves},
    {"wood", PatternKind::Wood},           {"wrinkles", PatternKind::Wrinkles},
    {"mandel", PatternKind::Mandel},       {"julia", PatternKind::Julia},
    {"brick", PatternKind::Brick},         {"hexagon", PatternKind::Hexagon},
    {"square", PatternKind::Square},       {"triangular", PatternKind::Triangular},
    {"cubic", PatternKind::Cubic},         {"checker", PatternKind::Checker},
    {"gradient", PatternKind::Gradient},   {"average", PatternKind::Average},
    {"function", PatternKind::Function},   {"density_file", PatternKind::DensityFile},
    {"object", PatternKind::Object},       {"pigment_pattern", PatternKind::PigmentPattern},
    {"image_pattern", PatternKind::ImagePattern},
    {"slope", PatternKind::Slope},
    {"aoi", PatternKind::Aoi},
    {"magnet", PatternKind::Magnet},       {"tiling", PatternKind::Tiling},
};

std::optional<PatternKind> pattern_keyword(const std::string& w) {
    for (const PatternWord& p : kPatternWords)
        if (w == p.name) return p.kind;
    return std::nullopt;
}

// POV-Ray patterns glint does not evaluate: named so the message is precise.
const std::unordered_set<std::string>& unsupported_patterns() {
    static const std::unordered_set<std::string> k = {
        "pavement",
        "gradient_map", "material_map"};
    return k;
}

// Parse_Blend_List's default colors (pigment.cpp Check/Brick/Hex/Square/Triangular/Cubic
// default maps; checker uses the hexagon entries, square and triangular the cubic ones).
Color block_default_color(PatternKind k, int i) {
    static const Color kHex[] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    static const Color kCubic[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                   {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    static const Color kBrick[] = {{0.5, 0.5, 0.5}, {0.6, 0.15, 0.15}};
    switch (k) {
        case PatternKind::Brick: return kBrick[i];
        case PatternKind::Checker:
        case PatternKind::Object:  // Check_Default_Map
        case PatternKind::Hexagon: return kHex[i];
        default: return kCubic[i];
    }
}

// Patterns that cannot take a continuous map (color_map, pigment_map, slope_map, ...).
bool takes_no_map(PatternKind k) {
    return block_count(k) > 0 || k == PatternKind::Plain || k == PatternKind::ImageMap;
}

// A pattern glint lacks (unsupported_patterns): warns once per feature, reads over the
// pattern's own arguments so the rest of the block parses, and makes the pattern a constant 0
// (a gradient along the zero vector): a pigment or texture shows its map's first entry, a
// normal stays smooth. Returns false for the keywords that carry a whole texture of their own
// (material_map, object), which leave the texture as it was.
bool skip_unsupported_pattern(Parser& p, const std::string& w, PatternKind* kind,
                              scene::PatternParams* params, const char* consequence) {
    // The object pattern's entries sit inside its own block: the pigment or texture stays as
    // it was without it.
    warn_unsupported(p, w, p.loc(),
                     w == "object" ? "the pigment or texture is left as it was" : consequence);
    if (w == "object" || w == "pigment_pattern" || w == "material_map" || w == "gradient_map") {
        skip_braced_block(p, w);
    } else if (w == "pavement") {
        while (p.accept("number_of_sides") || p.accept("number_of_tiles") ||
               p.accept("pattern") || p.accept("exterior") || p.accept("interior") ||
               p.accept("form"))
            p.parse_float();
    }
    if (w == "material_map" || w == "object") return false;
    *kind = PatternKind::Gradient;
    params->vector = Vec3(0, 0, 0);
    return true;
}

}  // namespace

int block_count(PatternKind k) {
    switch (k) {
        case PatternKind::Checker:
        case PatternKind::Object:
        case PatternKind::Brick: return 2;
        case PatternKind::Hexagon: return 3;
        case PatternKind::Square: return 4;
        case PatternKind::Triangular:
        case PatternKind::Cubic: return 6;
        default: return 0;
    }
}

// ---------------------------------------------------------------- pigment

void Parser::parse_pigment_body(scene::Pigment& p, bool one_item) {
    bool first = true;
    if (!p.loc.valid()) p.loc = loc();
    for (int items = 0; !one_item || items < 1; first = false, ++items) {
        const Token& t = next();
        if (is_body_end(t)) {
            unget();
            break;
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
            const std::string w = t.text;
            unget();
            Transform delta;
            if (parse_transform_item(delta)) {
                transform_pigment(p, delta);
                continue;
            }
            next();
            if (auto kind = pattern_keyword(w)) {
                p.kind = *kind;
                parse_pattern_arguments(*kind, p.params, false);
                if (int n = block_count(*kind)) {
                    p.entries = parse_pigment_entries(*kind, n);
                    p.color_map.clear();
                    p.pigment_map.clear();
                } else {
                    p.entries.clear();
                }
                if (*kind == PatternKind::Object) close_object_pattern();
            } else if (w == "color_map" || w == "colour_map") {
                if (takes_no_map(p.kind) || p.kind == PatternKind::Average)
                    fail("cannot use " + w + " with the '" + pattern_name(p.kind) + "' pattern");
                expect_open(w.c_str());
                FileLoc o = loc();
                p.color_map = parse_color_map_body();
                p.pigment_map.clear();
                expect_close(w.c_str(), o);
            } else if (w == "density_map") {
                if (!in_density_) fail("density_map can only be used in a density");
                if (takes_no_map(p.kind) || p.kind == PatternKind::Average)
                    fail("cannot use density_map with the '" +
                         std::string(pattern_name(p.kind)) + "' pattern");
                expect_open("density_map");
                FileLoc o = loc();
                p.pigment_map = parse_density_map_body();
                p.color_map.clear();
                expect_close("density_map", o);
            } else if (w == "pigment_map") {
                if (takes_no_map(p.kind))
                    fail("cannot use pigment_map with the '" + std::string(pattern_name(p.kind)) +
                         "' pattern");
                expect_open("pigment_map");
                FileLoc o = loc();
                p.pigment_map = parse_pigment_map_body(p.kind == PatternKind::Average);
                p.color_map.clear();
                expect_close("pigment_map", o);
            } else if (w == "image_map") {
                expect_open("image_map");
                FileLoc o = loc();
                p.kind = PatternKind::ImageMap;
                p.params.image = scene::ImageMap{};
                p.params.image.loc = o;
                parse_image_map_body(p.params.image);
                expect_close("image_map", o);
            } else if (w == "uv_mapping") {
                p.uv_mapping = true;
            } else if (w == "quick_color" || w == "quick_colour") {
                parse_color();  // only for POV-Ray's low-quality preview
            } else if (w == "normal_map" || w == "slope_map" || w == "texture_map") {
                fail("'" + w + "' cannot be used in a pigment");
            } else if (w == "bump_size" || w == "accuracy") {
                fail("'" + w + "' can only be used in a normal");
            } else if (parse_pattern_modifier(w, p.kind, p.params, p.transform)) {
            } else if (unsupported_patterns().count(w)) {
                skip_unsupported_pattern(*this, w, &p.kind, &p.params,
                                         "the pattern is constant 0 (its map's first entry)");
            } else {
                unget();
                if (!next_is_expression_start())
                    fail("expected a pigment item (color, pattern, transform, ...), got " +
                         got(next()));
                p.kind = PatternKind::Plain;
                p.color = parse_color();
            }
            continue;
        }
        unget();
        if (!next_is_expression_start())
            fail("expected a pigment item (color, pattern, transform, ...), got " + got(next()));
        p.kind = PatternKind::Plain;
        p.color = parse_color();
    }
    if (p.kind == PatternKind::Average && p.pigment_map.empty())
        fail("an average pigment needs a pigment_map");
}

// Parse_Blend_List for pigments: `pigment {..}` entries, or colors; missing ones are the
// pattern's default colors (for color lists) or the default pigment.
std::vector<scene::Pigment> Parser::parse_pigment_entries(PatternKind kind, int count) {
    std::vector<scene::Pigment> e;
    skip_comma();
    bool pigments = raw_next_is("pigment");
    for (int i = 0; i < count; ++i) {
        if (pigments) {
            if (!accept("pigment")) break;
            expect_open("pigment");
            FileLoc o = loc();
            scene::Pigment sub = default_texture_.pigment;
            sub.loc = o;
            parse_pigment_body(sub);
            expect_close("pigment", o);
            e.push_back(sub);
        } else {
            if (!next_is_expression_start()) break;
            scene::Pigment sub;
            sub.loc = loc();
            sub.color = parse_color();
            e.push_back(sub);
        }
        skip_comma();
    }
    while (static_cast<int>(e.size()) < count) {
        scene::Pigment d = pigments ? default_texture_.pigment : scene::Pigment{};
        if (!pigments) d.color = scene::ColorFT(block_default_color(kind, static_cast<int>(e.size())));
        e.push_back(d);
    }
    return e;
}

// ---------------------------------------------------------------- normal

void Parser::parse_normal_body(scene::Normal& n, bool one_item) {
    bool first = true;
    if (!n.loc.valid()) n.loc = loc();
    for (int items = 0; !one_item || items < 1; first = false, ++items) {
        const Token& t = next();
        if (is_body_end(t)) {
            unget();
            break;
        }
        if (take_body_identifier(t, first, "a", "normal", n)) {
            // POV-Ray reads the amount after the pattern, with or without a keyword.
            skip_comma();
            n.amount = allow_float(n.amount);
            continue;
        }
        unget();
        Transform tr = n.transform;
        if (parse_transform_item(tr)) {
            n.transform = tr;
            continue;
        }
        const Token& k = next();
        const std::string w = k.kind == TokKind::Word ? k.text : std::string();
        if (auto kind = pattern_keyword(w)) {
            // Create_Tnormal: a new normal's amount is 0.5.
            if (n.kind == PatternKind::Plain && n.amount == 0) n.amount = 0.5;
            n.kind = *kind;
            parse_pattern_arguments(*kind, n.params, true);
            n.entries.clear();
            if (int c = block_count(*kind)) {
                n.accuracy = 0.02;
                n.entries = parse_normal_entries(c);
                n.slope_map.clear();
                n.normal_map.clear();
            }
            if (*kind == PatternKind::Object) close_object_pattern();
            skip_comma();
            n.amount = allow_float(n.amount);
        } else if (w == "bump_map") {
            if (n.kind == PatternKind::Plain && n.amount == 0) n.amount = 0.5;
            expect_open("bump_map");
            FileLoc o = loc();
            n.kind = PatternKind::ImageMap;
            n.params.image = scene::ImageMap{};
            n.params.image.loc = o;
            parse_image_map_body(n.params.image, &n.amount);
            expect_close("bump_map", o);
            // Parse_Image without gamma correction: bump heights are the values as stored.
            if (n.params.image.gamma == 0) n.params.image.gamma = 1.0;
            skip_comma();
            n.amount = allow_float(n.amount);
        } else if (w == "bump_size") {
            n.amount = parse_float();
        } else if (w == "accuracy") {
            n.accuracy = parse_float();
        } else if (w == "slope_map") {
            if (takes_no_map(n.kind) || n.kind == PatternKind::Average)
                fail("cannot use slope_map with the '" + std::string(pattern_name(n.kind)) +
                     "' pattern");
            expect_open("slope_map");
            FileLoc o = loc();
            n.slope_map = parse_slope_map_body();
            expect_close("slope_map", o);
        } else if (w == "normal_map") {
            if (takes_no_map(n.kind) || n.kind == PatternKind::Facets)
                fail("cannot use normal_map with the '" + std::string(pattern_name(n.kind)) +
                     "' pattern");
            expect_open("normal_map");
            FileLoc o = loc();
            n.normal_map = parse_normal_map_body(n.kind == PatternKind::Average);
            expect_close("normal_map", o);
        } else if (w == "uv_mapping") {
            n.uv_mapping = true;
        } else if (w == "color_map" || w == "colour_map" || w == "pigment_map" ||
                   w == "texture_map") {
            fail("'" + w + "' cannot be used in a normal");
        } else if (w == "image_map") {
            fail("'image_map' can only be used in a pigment (use bump_map in a normal)");
        } else if (!w.empty() && parse_pattern_modifier(w, n.kind, n.params, n.transform)) {
        } else if (unsupported_patterns().count(w)) {
            skip_unsupported_pattern(*this, w, &n.kind, &n.params,
                                     "the normal is not perturbed by it");
            skip_comma();
            n.amount = allow_float(n.amount);
        } else {
            fail("expected a normal pattern or modifier, got " + got(k));
        }
    }
    if (n.kind == PatternKind::Average && n.normal_map.empty())
        fail("an average normal needs a normal_map");
}

// Parse_Blend_List for normals: `normal {..}` entries; none at all means the pattern's own
// values are the slope (POV-Ray keeps no map); missing ones are the default normal.
std::vector<scene::Normal> Parser::parse_normal_entries(int count) {
    std::vector<scene::Normal> e;
    skip_comma();
    for (int i = 0; i < count; ++i) {
        if (!accept("normal")) break;
        expect_open("normal");
        FileLoc o = loc();
        scene::Normal sub = default_texture_.normal;
        sub.loc = o;
        parse_normal_body(sub);
        expect_close("normal", o);
        e.push_back(sub);
        skip_comma();
    }
    if (e.empty()) return e;
    while (static_cast<int>(e.size()) < count) e.push_back(default_texture_.normal);
    return e;
}

// ---------------------------------------------------------------- texture

scene::Texture& top_layer(scene::Texture& t) { return t.layers.empty() ? t : t.layers.back(); }

void layer_texture(scene::Texture& base, const scene::Texture& top, const FileLoc& at) {
    // Link_Textures: layers are plain textures only.
    if (base.kind != PatternKind::Plain)
        throw Error(ErrorKind::Scene, at, "cannot layer over a patterned texture");
    if (top.kind != PatternKind::Plain)
        throw Error(ErrorKind::Scene, at, "cannot layer a patterned texture over another");
    scene::Texture t = top;
    std::vector<scene::Texture> above = std::move(t.layers);
    t.layers.clear();
    base.layers.push_back(std::move(t));
    for (auto& l : above) base.layers.push_back(std::move(l));
}

// The items POV-Ray 1.0 wrote straight in a texture, each read as in its own block
// (Parse_Vers1_Texture's lists; newer keywords were never added there).
bool Parser::parse_old_texture_item(const Token& t, scene::Texture& top) {
    static const std::unordered_set<std::string> kPigment = {
        "agate",       "bozo",         "granite",   "leopard",    "marble",    "mandel",
        "onion",       "spotted",      "wood",      "gradient",   "checker",   "hexagon",
        "square",      "triangular",   "image_map", "turbulence", "color_map", "colour_map",
        "quick_color", "quick_colour", "octaves",   "omega",      "lambda",    "color",
        "colour",      "rgb",          "rgbf",      "rgbt",       "rgbft",     "red",
        "green",       "blue"};
    static const std::unordered_set<std::string> kNormal = {
        "bumps", "dents", "ripples", "waves", "wrinkles", "bump_map", "frequency", "phase"};
    static const std::unordered_set<std::string> kFinish = {
        "ambient",  "brilliance", "diffuse",  "reflection", "phong", "phong_size",
        "specular", "roughness",  "metallic", "crand",      "ior",   "refraction"};
    if (t.kind != TokKind::Word) return false;
    const Symbol* s = lookup(t.text);
    const bool colour_id = s && std::holds_alternative<Num>(s->value);  // a colour identifier
    if (s && !colour_id) return false;
    const bool pigment = colour_id || kPigment.count(t.text);
    if (!pigment && !kNormal.count(t.text) && !kFinish.count(t.text)) return false;
    if (!warned_old_texture_) {
        diag.warning(loc(), "'" + t.text + "' straight in a texture is POV-Ray 1.0 syntax (the " +
                                "scene's #version is below 3.0): read as POV-Ray reads it; newer " +
                                "scenes put it in pigment { }, normal { } or finish { }");
        warned_old_texture_ = true;
    }
    unget();
    if (pigment)
        parse_pigment_body(top.pigment, true);
    else if (kNormal.count(t.text))
        parse_normal_body(top.normal, true);
    else
        parse_finish_body(top.finish, true);
    return true;
}

scene::Texture Parser::parse_texture_body() {
    // `#version` below 3.0: POV-Ray reads textures in its 1.0 syntax (Parse_Vers1_Texture).
    const bool old_syntax = version_set() && version() < 3.0;
    scene::Texture tex = default_texture_;
    tex.loc = loc();
    bool first = true;
    bool modified = false;  // has a pigment, normal or finish: cannot become patterned
    bool uv_plain = false;  // `uv_mapping` in a plain texture
    // A pattern that was left out (object, tiles, material_map): its modifiers are read over.
    bool dropped_pattern = false;
    scene::PatternParams dropped_params;
    Transform dropped_transform;
    for (;; first = false) {
        const Token& t = next();
        if (is_body_end(t)) {
            unget();
            break;
        }
        if (old_syntax && tex.kind == PatternKind::Plain &&
            parse_old_texture_item(t, top_layer(tex))) {
            modified = true;
            continue;
        }
        if (t.kind == TokKind::Word && lookup(t.text)) {
            const Symbol& s = use_symbol(t);
            // texture { PIGMENT_ID } etc. (POV-Ray's backward-compatible shorthand)
            if (auto pg = std::get_if<scene::Pigment>(&s.value)) {
                top_layer(tex).pigment = *pg;
                modified = true;
                continue;
            }
            if (auto nm = std::get_if<scene::Normal>(&s.value)) {
                top_layer(tex).normal = *nm;
                modified = true;
                continue;
            }
            if (auto fi = std::get_if<scene::Finish>(&s.value)) {
                top_layer(tex).finish = *fi;
                modified = true;
                continue;
            }
            if (take_body_identifier(t, first, "a", "texture", tex)) {
                modified = true;
                continue;
            }
        }
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        if (w == "pigment" || w == "normal" || w == "finish") {
            if (tex.kind != PatternKind::Plain)
                fail("a patterned texture cannot take a " + w + " (put it in the map entries)");
            scene::Texture& top = top_layer(tex);
            expect_open(w.c_str());
            FileLoc o = loc();
            if (w == "pigment") parse_pigment_body(top.pigment);
            else if (w == "normal") parse_normal_body(top.normal);
            else parse_finish_body(top.finish);
            expect_close(w.c_str(), o);
            modified = true;
        } else if (auto kind = pattern_keyword(w)) {
            if (modified && tex.kind == PatternKind::Plain)
                fail("a texture with a pigment, normal or finish cannot also have a pattern");
            if (*kind == PatternKind::Facets) fail("'facets' can only be used in a normal");
            tex.kind = *kind;
            tex.pigment = scene::Pigment{};
            tex.normal = scene::Normal{};
            tex.layers.clear();
            parse_pattern_arguments(*kind, tex.params, false);
            tex.entries.clear();
            if (int n = block_count(*kind)) {
                tex.entries = parse_texture_entries(n);
                tex.texture_map.clear();
            }
            if (*kind == PatternKind::Object) close_object_pattern();
        } else if (w == "material_map") {
            if (modified && tex.kind == PatternKind::Plain)
                fail("a texture with a pigment, normal or finish cannot also have a material_map");
            parse_material_map(tex);
        } else if (w == "tiles") {
            if (modified && tex.kind == PatternKind::Plain)
                fail("a texture with a pigment, normal or finish cannot also have tiles");
            parse_tiles(tex);
        } else if (w == "texture_map") {
            if (takes_no_map(tex.kind))
                fail("cannot use texture_map with the '" + std::string(pattern_name(tex.kind)) +
                     "' pattern");
            expect_open("texture_map");
            FileLoc o = loc();
            tex.texture_map = parse_texture_map_body(tex.kind == PatternKind::Average);
            expect_close("texture_map", o);
        } else if (w == "uv_mapping" && tex.kind != PatternKind::Plain) {
            tex.uv_mapping = true;
        } else if (w == "uv_mapping") {
            // A plain texture's uv_mapping maps its pigment and normal (POV-Ray's
            // Post_Textures passes the flag down), whenever they are given.
            uv_plain = true;
        } else if (w == "color_map" || w == "colour_map" || w == "pigment_map" ||
                   w == "normal_map" || w == "slope_map") {
            fail("'" + w + "' cannot be used directly in a texture");
        } else if (!w.empty() && tex.kind != PatternKind::Plain &&
                   parse_pattern_modifier(w, tex.kind, tex.params, tex.transform)) {
        } else if (!w.empty() && dropped_pattern &&
                   parse_pattern_modifier(w, PatternKind::Gradient, dropped_params,
                                          dropped_transform)) {
            // a modifier (warp, turbulence, ...) of the pattern that was left out
        } else if (unsupported_patterns().count(w)) {
            if (skip_unsupported_pattern(*this, w, &tex.kind, &tex.params,
                                         "the texture is its texture_map's first entry")) {
                tex.pigment = scene::Pigment{};
                tex.normal = scene::Normal{};
                tex.layers.clear();
            } else {
                dropped_pattern = true;
            }
        } else {
            unget();
            Transform tr;
            if (!parse_transform_item(tr))
                fail("expected a texture item (pigment, normal, finish, pattern, transform), "
                     "got " + got(next()));
            transform_texture(tex, tr);
        }
    }
    if (tex.kind != PatternKind::Plain && tex.kind != PatternKind::ImageMap &&
        block_count(tex.kind) == 0 && tex.texture_map.empty())
        fail("a patterned texture needs a texture_map");
    if (uv_plain) {
        scene::Texture& top = top_layer(tex);
        top.pigment.uv_mapping = true;
        top.normal.uv_mapping = true;
    }
    return tex;
}

void Parser::parse_material_map(scene::Texture& tex) {
    // Parse_Material_Map: a new texture (what came before is dropped, transforms too) whose
    // image's pixels choose among the textures that follow the image items.
    expect_open("material_map");
    FileLoc o = loc();
    scene::Texture m;
    m.loc = tex.loc;
    m.kind = PatternKind::ImageMap;
    m.params.image.loc = o;
    parse_image_map_body(m.params.image, nullptr, true);
    while (accept("texture")) {
        expect_open("texture");
        FileLoc to = loc();
        m.entries.push_back(parse_texture_body());
        expect_close("texture", to);
    }
    if (m.entries.empty()) fail("a material_map needs at least one texture");
    expect_close("material_map", o);
    tex = std::move(m);
}

// tiles { texture {..}... tile2 texture {..}... } (Parse_Tiles): POV-Ray's older spelling of a
// checker of two textures. Its first texture fills the checker's second cell and tile2's the
// first, so it is stored as `checker texture {tile2's} texture {first}`. Several textures in
// one slot are layered; a slot left empty takes the default texture.
void Parser::parse_tiles(scene::Texture& tex) {
    expect_open("tiles");
    const FileLoc opened = loc();
    auto layered_slot = [&](bool* given) {
        scene::Texture slot = default_texture_;
        *given = false;
        for (;;) {
            const FileLoc at = loc();
            if (!accept("texture")) break;
            expect_open("texture");
            const FileLoc o = loc();
            scene::Texture t = parse_texture_body();
            expect_close("texture", o);
            if (*given) layer_texture(slot, t, at);
            else slot = std::move(t);
            *given = true;
        }
        return slot;
    };
    bool given = false;
    scene::Texture first = layered_slot(&given);
    if (!given) fail_at(opened, "first texture missing from tiles");
    if (!accept("tile2")) fail("expected tile2 in tiles, got " + got(peek()));
    scene::Texture second = layered_slot(&given);
    expect_close("tiles", opened);
    tex.kind = PatternKind::Checker;
    tex.pigment = scene::Pigment{};
    tex.normal = scene::Normal{};
    tex.layers.clear();
    tex.params = scene::PatternParams{};
    tex.params.frequency = 0;  // a block pattern, as parse_pattern_arguments leaves it
    tex.texture_map.clear();
    tex.entries = {std::move(second), std::move(first)};
}

std::vector<scene::Texture> Parser::parse_texture_entries(int count) {
    std::vector<scene::Texture> e;
    skip_comma();
    for (int i = 0; i < count; ++i) {
        if (!accept("texture")) break;
        expect_open("texture");
        FileLoc o = loc();
        e.push_back(parse_texture_body());
        expect_close("texture", o);
        skip_comma();
    }
    while (static_cast<int>(e.size()) < count) e.push_back(default_texture_);
    return e;
}

}  // namespace glint::pov
