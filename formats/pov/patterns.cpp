// Patterned pigments, normals and textures (reference manual 3.4.11 "Patterns", 3.4.6 "Texture
// maps"; parstxtr.cpp Parse_Pattern/Parse_Warp and express.cpp Parse_Blend_Map/Parse_Blend_List/
// Parse_Colour_Map in POV-Ray 3.7): the pattern keywords with their arguments, the modifiers they
// share, warps, blend maps and the entry lists of block patterns. Each body function reads items
// up to the closing '}' (or ']' inside a map entry) and leaves it for the caller.
//
// Pattern space: a pattern's own `transform` is POV-Ray's leading TRANSFORM_WARP (the most
// recent transforms); `params.warps` are the rest of POV-Ray's warp list in the order they are
// applied to the point. A warp { } block goes in front (it is applied before the transforms
// written earlier), and turbulence written in the pattern modifies or appends a classic
// turbulence warp at the end (Check_Turb). Map and block entries are evaluated in the parent's
// warped pattern space, so their transforms are relative to the parent's.
#include <cmath>
#include <optional>
#include <unordered_set>

#include "formats/pov/parser_impl.h"
#include "formats/pov/unsupported.h"

namespace glint::pov {

namespace {

using scene::PatternKind;
using scene::WarpKind;

enum class Use { Pigment, Normal, Texture };

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
    {"function", PatternKind::Function},
};

std::optional<PatternKind> pattern_keyword(const std::string& w) {
    for (const PatternWord& p : kPatternWords)
        if (w == p.name) return p.kind;
    return std::nullopt;
}

// POV-Ray patterns glint does not evaluate: named so the message is precise.
const std::unordered_set<std::string>& unsupported_patterns() {
    static const std::unordered_set<std::string> k = {
        "aoi", "density_file", "image_pattern", "object", "pavement",
        "pigment_pattern", "slope", "tiling", "magnet", "gradient_map", "material_map", "tiles"};
    return k;
}

// Number of entries of a block pattern (0 for the others).
int block_count(PatternKind k) {
    switch (k) {
        case PatternKind::Checker:
        case PatternKind::Brick: return 2;
        case PatternKind::Hexagon: return 3;
        case PatternKind::Square: return 4;
        case PatternKind::Triangular:
        case PatternKind::Cubic: return 6;
        default: return 0;
    }
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
        case PatternKind::Hexagon: return kHex[i];
        default: return kCubic[i];
    }
}

// Patterns that cannot take a continuous map (color_map, pigment_map, slope_map, ...).
bool takes_no_map(PatternKind k) {
    return block_count(k) > 0 || k == PatternKind::Plain || k == PatternKind::ImageMap;
}

// POV-Ray's Check_Turb: the classic turbulence warp at the end of the list, made if missing.
scene::Turbulence& classic_turbulence(scene::PatternParams& pp, const FileLoc& l) {
    if (pp.warps.empty() || pp.warps.back().kind != WarpKind::ClassicTurbulence) {
        scene::Warp w;
        w.kind = WarpKind::ClassicTurbulence;
        w.loc = l;
        pp.warps.push_back(w);
    }
    return pp.warps.back().turbulence;
}

// A warp { } block goes before everything written so far (POV-Ray prepends it), so the
// pattern's leading transform becomes an ordinary transform warp behind it.
void prepend_warp(scene::PatternParams& pp, Transform& head, const scene::Warp& w) {
    if (!head.is_identity()) {
        scene::Warp t;
        t.kind = WarpKind::Transform;
        t.transform = head;
        t.loc = w.loc;
        pp.warps.insert(pp.warps.begin(), t);
        head = Transform();
    }
    pp.warps.insert(pp.warps.begin(), w);
}

int clamp_octaves(double v) {
    int o = to_int(v);
    return o < 1 ? 1 : (o > 10 ? 10 : o);  // POV-Ray avoids domain errors past 10
}

// A pattern glint lacks (unsupported_patterns): warns once per feature, reads over the
// pattern's own arguments so the rest of the block parses, and makes the pattern a constant 0
// (a gradient along the zero vector): a pigment or texture shows its map's first entry, a
// normal stays smooth. Returns false for the keywords that carry a whole texture of their own
// (tiles, material_map), which leave the texture as it was.
bool skip_unsupported_pattern(Parser& p, const std::string& w, PatternKind* kind,
                              scene::PatternParams* params, const char* consequence) {
    if (w == "magnet") {  // magnet N mandel I | magnet N julia <c>, I
        warn_unsupported(p, w, p.loc(), "drawn as the mandel pattern with its iterations");
        p.parse_float();
        bool julia = p.accept("julia");
        if (!julia) p.accept("mandel");
        if (julia) {
            p.parse_vector();
            p.skip_comma();
        }
        // Its interior/exterior modifiers still parse: they are the fractal ones.
        *kind = PatternKind::Mandel;
        params->iterations = to_int(p.parse_float());
        return true;
    }
    // The object pattern's entries sit inside its own block: the pigment or texture stays as
    // it was without it.
    warn_unsupported(p, w, p.loc(),
                     w == "object" ? "the pigment or texture is left as it was" : consequence);
    if (w == "object" || w == "pigment_pattern" || w == "image_pattern" || w == "tiles" ||
        w == "material_map" || w == "gradient_map") {
        skip_braced_block(p, w);
    } else if (w == "density_file") {
        p.next();  // df3
        p.parse_string();
        if (p.accept("interpolate")) p.parse_float();
    } else if (w == "tiling") {
        p.parse_float();
    } else if (w == "slope") {  // slope <v> [, lo, hi] [altitude <v> [, lo, hi]] or { ... }
        if (p.peek().is_symbol('{')) {
            skip_braced_block(p, w);
        } else {
            for (bool first = true; first || p.accept("altitude"); first = false) {
                p.parse_vector();
                if (p.accept(",")) {
                    p.parse_float();
                    p.skip_comma();
                    p.parse_float();
                }
            }
        }
    } else if (w == "aoi") {
        if (p.next_is_expression_start()) p.parse_vector();
    } else if (w == "pavement") {
        while (p.accept("number_of_sides") || p.accept("number_of_tiles") ||
               p.accept("pattern") || p.accept("exterior") || p.accept("interior") ||
               p.accept("form"))
            p.parse_float();
    }
    if (w == "tiles" || w == "material_map" || w == "object") return false;
    *kind = PatternKind::Gradient;
    params->vector = Vec3(0, 0, 0);
    return true;
}

}  // namespace

// ---------------------------------------------------------------- shared pattern grammar

// The arguments of a pattern keyword (already read). Block pattern entries are read by the
// caller, which knows what they are (colors, pigments, normals, textures).
void Parser::parse_pattern_arguments(PatternKind kind, scene::PatternParams& pp, bool normal) {
    FileLoc l = loc();
    switch (kind) {
        case PatternKind::Agate:
            pp.agate_turb = 1.0;
            classic_turbulence(pp, l);  // agate reads octaves, omega and lambda from it
            break;
        case PatternKind::Marble:
        case PatternKind::Wood:
            pp.wave = scene::WaveType::Triangle;
            break;
        case PatternKind::Spiral1:
        case PatternKind::Spiral2:
            pp.arms = to_int(parse_float());
            pp.wave = scene::WaveType::Triangle;
            break;
        case PatternKind::Gradient: {
            peek();
            FileLoc vl = loc();
            Vec3 v = parse_vector();
            if (length(v) == 0) fail_at(vl, "gradient vector has zero length");
            pp.vector = normalize(v);  // POV-Ray normalizes it
            break;
        }
        case PatternKind::Mandel:
        case PatternKind::Julia:
            if (kind == PatternKind::Julia) {
                Num c = parse_num(2);
                pp.julia_param = Vec2(c.v[0], c.v[1]);
                skip_comma();
            }
            pp.iterations = to_int(parse_float());
            pp.interior_type = 0;
            pp.exterior_type = 1;
            pp.interior_factor = pp.exterior_factor = 1;
            pp.fractal_exponent = 2;
            break;
        case PatternKind::Function:  // function { expression } (functions.cpp)
            pp.function = parse_function_definition();
            break;
        case PatternKind::Crackle:
            pp.crackle_solid = false;
            pp.crackle_form = Vec3(-1, 1, 0);
            pp.crackle_metric = 2;
            pp.crackle_offset = 0;
            break;
        case PatternKind::Brick:
            pp.brick_size = Vec3(8, 3, 4.5);
            pp.mortar = 0.5;
            break;
        case PatternKind::Quilted:
            pp.control0 = pp.control1 = 1;
            pp.frequency = 0;  // POV-Ray: quilted values are not reshaped by default
            break;
        case PatternKind::Facets:
            if (!normal) fail_at(l, "'facets' can only be used in a normal");
            pp.facets_size = 0.1;
            pp.facets_coords = 0;
            pp.facets_metric = 2;
            break;
        default: break;
    }
    if (block_count(kind) > 0) pp.frequency = 0;
}

bool Parser::parse_pattern_modifier(const std::string& w, PatternKind kind,
                                    scene::PatternParams& pp, Transform& head) {
    auto only = [&](bool ok, const char* what) {
        if (!ok) fail("'" + w + "' applies only to " + what + " patterns");
    };
    const bool fractal = kind == PatternKind::Mandel || kind == PatternKind::Julia;
    if (w == "turbulence") {
        FileLoc l = loc();
        classic_turbulence(pp, l).amount = parse_vector();
    } else if (w == "octaves") {
        FileLoc l = loc();
        classic_turbulence(pp, l).octaves = clamp_octaves(parse_float());
    } else if (w == "omega") {
        FileLoc l = loc();
        classic_turbulence(pp, l).omega = parse_float();
    } else if (w == "lambda") {
        FileLoc l = loc();
        classic_turbulence(pp, l).lambda = parse_float();
    } else if (w == "frequency") {
        pp.frequency = parse_float();
    } else if (w == "phase") {
        pp.phase = parse_float();
    } else if (w == "ramp_wave") {
        pp.wave = scene::WaveType::Ramp;
    } else if (w == "triangle_wave") {
        pp.wave = scene::WaveType::Triangle;
    } else if (w == "sine_wave") {
        pp.wave = scene::WaveType::Sine;
    } else if (w == "scallop_wave") {
        pp.wave = scene::WaveType::Scallop;
    } else if (w == "cubic_wave") {
        pp.wave = scene::WaveType::Cubic;
    } else if (w == "poly_wave") {
        pp.wave = scene::WaveType::Poly;
        pp.wave_exponent = allow_float(pp.wave_exponent);
    } else if (w == "noise_generator") {
        peek();
        FileLoc l = loc();
        double g = parse_float();
        if (g < 0 || g > 3) fail_at(l, "noise_generator must be 0, 1, 2 or 3");
        pp.noise_generator = static_cast<int>(g);
    } else if (w == "agate_turb") {
        only(kind == PatternKind::Agate, "agate");
        FileLoc l = loc();
        pp.agate_turb = parse_float();
        classic_turbulence(pp, l);
    } else if (w == "brick_size") {
        only(kind == PatternKind::Brick, "brick");
        pp.brick_size = parse_vector();
    } else if (w == "mortar") {
        only(kind == PatternKind::Brick, "brick");
        pp.mortar = parse_float();
    } else if (w == "control0" || w == "control1") {
        only(kind == PatternKind::Quilted, "quilted");
        (w == "control0" ? pp.control0 : pp.control1) = parse_float();
    } else if (w == "solid") {
        only(kind == PatternKind::Crackle, "crackle");
        pp.crackle_solid = true;
    } else if (w == "form") {
        only(kind == PatternKind::Crackle, "crackle");
        pp.crackle_form = parse_vector();
    } else if (w == "offset") {
        only(kind == PatternKind::Crackle, "crackle");
        pp.crackle_offset = parse_float();
    } else if (w == "metric") {
        only(kind == PatternKind::Crackle || kind == PatternKind::Facets, "crackle and facets");
        double m = parse_vector().x;  // a vector for compatibility; only x was ever used
        (kind == PatternKind::Crackle ? pp.crackle_metric : pp.facets_metric) = m;
    } else if (w == "coords") {
        only(kind == PatternKind::Facets, "facets");
        pp.facets_coords = parse_float();
    } else if (w == "size") {
        only(kind == PatternKind::Facets, "facets");
        pp.facets_size = parse_float();
    } else if (w == "exterior" || w == "interior") {
        only(fractal, "mandel and julia");
        FileLoc l = loc();
        int type = to_int(parse_float());
        bool ext = w == "exterior";
        if (type < 0 || type > (ext ? 8 : 6))
            fail_at(l, std::string("fractal ") + w + " type must be 0 to " + (ext ? "8" : "6"));
        skip_comma();
        double factor = parse_float();
        if (ext) {
            pp.exterior_type = type;
            pp.exterior_factor = factor;
        } else {
            pp.interior_type = type;
            pp.interior_factor = factor;
        }
    } else if (w == "exponent") {
        only(fractal, "mandel and julia");
        FileLoc l = loc();
        int e = to_int(parse_float());
        if (e < 2 || e > 33) {
            diag.warning(l, "fractal exponent must be 2 to 33; using 2");
            e = 2;
        }
        pp.fractal_exponent = e;
    } else if (w == "warp") {
        FileLoc l = loc();
        expect_open("warp");
        FileLoc o = loc();
        scene::Warp wp = parse_warp_body(l);
        expect_close("warp", o);
        prepend_warp(pp, head, wp);
    } else if (w == "no_bump_scale") {
        diag.warning(loc(), "'no_bump_scale' is not supported; bumps are scaled");
    } else {
        return false;
    }
    return true;
}

scene::Warp Parser::parse_warp_body(const FileLoc& at) {
    scene::Warp w;
    w.loc = at;
    const Token& t = next();
    const std::string k = t.kind == TokKind::Word ? t.text : std::string();
    if (k == "turbulence") {
        w.kind = WarpKind::Turbulence;
        w.turbulence.amount = parse_vector();
        for (;;) {
            if (accept("octaves")) w.turbulence.octaves = clamp_octaves(parse_float());
            else if (accept("omega")) w.turbulence.omega = parse_float();
            else if (accept("lambda")) w.turbulence.lambda = parse_float();
            else break;
        }
    } else if (k == "repeat") {
        w.kind = WarpKind::Repeat;
        peek();
        FileLoc l = loc();
        w.direction = parse_vector();
        int axes = (w.direction.x != 0) + (w.direction.y != 0) + (w.direction.z != 0);
        if (axes == 0) fail_at(l, "no axis given in repeat");
        if (axes > 1) fail_at(l, "a repeat warp repeats along one axis only");
        for (;;) {
            if (accept("offset")) w.offset = parse_vector();
            else if (accept("flip")) w.flip = parse_vector();
            else break;
        }
    } else if (k == "black_hole") {
        w.kind = WarpKind::BlackHole;
        w.center = parse_vector();
        skip_comma();
        w.radius = parse_float();
        for (;;) {
            if (accept("strength")) w.strength = parse_float();
            else if (accept("falloff")) w.falloff = parse_float();
            else if (accept("inverse")) w.inverse = true;
            else if (accept("type")) parse_float();  // only type 0 exists
            else if (accept("repeat")) w.repeat = parse_vector();
            else if (accept("turbulence")) w.turbulence.amount = parse_vector();
            else break;
        }
    } else if (k == "cylindrical" || k == "spherical" || k == "toroidal") {
        w.kind = k == "cylindrical" ? WarpKind::Cylindrical
                 : k == "spherical" ? WarpKind::Spherical
                                    : WarpKind::Toroidal;
        for (;;) {
            if (accept("orientation")) {
                Vec3 v = parse_vector();
                if (length(v) > 0) w.orientation = normalize(v);
            } else if (accept("dist_exp")) {
                w.dist_exp = parse_float();
            } else if (w.kind == WarpKind::Toroidal && accept("major_radius")) {
                w.major_radius = parse_float();
            } else {
                break;
            }
        }
    } else if (k == "planar") {
        w.kind = WarpKind::Planar;
        if (next_is_expression_start()) {
            Vec3 v = parse_vector();
            if (length(v) > 0) w.orientation = normalize(v);
            skip_comma();
            w.planar_offset = parse_float();
        }
    } else if (k == "cubic") {
        w.kind = WarpKind::Cubic;
    } else {
        fail("expected a warp type (turbulence, repeat, black_hole, cylindrical, spherical, "
             "toroidal, planar, cubic), got " + got(t));
    }
    return w;
}

// ---------------------------------------------------------------- maps

std::vector<scene::ColorMapEntry> Parser::parse_color_map_body() {
    // color_map { M } with a declared map.
    const Token& f = next();
    if (f.kind == TokKind::Word && lookup(f.text)) {
        const Symbol& s = use_symbol(f);
        if (auto m = std::get_if<BlendMapValue>(&s.value)) {
            if (m->keyword != "color_map")
                fail("expected a color_map, got a " + m->keyword + " '" + f.text + "'");
            return m->colors;
        }
    }
    unget();
    std::vector<scene::ColorMapEntry> map;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}') || t.kind == TokKind::End) {
            unget();
            break;
        }
        if (!t.is_symbol('['))
            fail("expected '[' to start a color_map entry, got " + got(t));
        FileLoc o = loc();
        double v1 = parse_float();
        bool old_syntax = false;
        // `[v1, v2 color c1 color c2]` (old, the comma optional) or `[v, color]`.
        skip_comma();
        const Token& n = peek();
        old_syntax = n.kind == TokKind::Number || n.is("-") || n.is("+");
        if (old_syntax) {
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
    if (map.empty()) fail("a color_map needs at least one entry");
    if (map.size() > 256) fail("a color_map has at most 256 entries");
    // Parse_Colour_Map drops an entry identical to the one before it.
    std::vector<scene::ColorMapEntry> out;
    for (const auto& e : map) {
        if (!out.empty() && out.back().value == e.value && out.back().color == e.color) continue;
        out.push_back(e);
    }
    return out;
}

// Reads `[v ITEM]` entries up to '}'; `item` reads one entry's body after its value.
template <class F>
void Parser::parse_map_entries(const char* what, bool average, F item) {
    int count = 0;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}') || t.kind == TokKind::End) {
            unget();
            break;
        }
        if (!t.is_symbol('['))
            fail(std::string("expected '[' to start a ") + what + " entry, got " + got(t));
        FileLoc o = loc();
        // average maps: the weight may be left out (1). POV-Ray's float here has no
        // comparisons, so in `[0 <0, 1>]` the '<' starts the slope vector.
        double v = 1.0;
        const Token& n = next();
        if (n.kind == TokKind::Number && raw_next_is("<")) {
            v = n.number;
        } else {
            unget();
            const std::string& w = peek().text;
            const bool colour = peek().kind == TokKind::Word &&
                                (w.rfind("rgb", 0) == 0 || w.rfind("srgb", 0) == 0 ||
                                 w == "color" || w == "colour");
            v = average ? (colour ? 1.0 : allow_float(1.0)) : parse_float();
        }
        skip_comma();
        item(v);
        const Token& c = next();
        if (!c.is_symbol(']'))
            fail(std::string("expected ']' to close the ") + what + " entry opened at " +
                 std::to_string(o.line) + ":" + std::to_string(o.column) + ", got " + got(c));
        if (++count > 256) fail(std::string("a ") + what + " has at most 256 entries");
    }
    if (count == 0) fail(std::string("a ") + what + " needs at least one entry");
}

// A declared map used inside map braces: `pigment_map { M }`. Returns null if the next token
// is not an identifier of a map.
const BlendMapValue* Parser::declared_map(const char* keyword) {
    const Token& f = next();
    if (f.kind == TokKind::Word && lookup(f.text)) {
        const Symbol& s = use_symbol(f);
        if (auto m = std::get_if<BlendMapValue>(&s.value)) {
            if (m->keyword != keyword)
                fail(std::string("expected a ") + keyword + ", got a " + m->keyword + " '" +
                     f.text + "'");
            return m;
        }
    }
    unget();
    return nullptr;
}

std::vector<scene::PigmentMapEntry> Parser::parse_pigment_map_body(bool average) {
    if (auto m = declared_map("pigment_map")) return m->pigments;
    std::vector<scene::PigmentMapEntry> map;
    parse_map_entries("pigment_map", average, [&](double v) {
        scene::Pigment p = default_texture_.pigment;
        p.loc = loc();
        parse_pigment_body(p);
        map.push_back({v, {p}});
    });
    return map;
}

std::vector<scene::NormalMapEntry> Parser::parse_normal_map_body(bool average) {
    if (auto m = declared_map("normal_map")) return m->normals;
    std::vector<scene::NormalMapEntry> map;
    parse_map_entries("normal_map", average, [&](double v) {
        scene::Normal n = default_texture_.normal;
        n.loc = loc();
        parse_normal_body(n);
        map.push_back({v, {n}});
    });
    return map;
}

std::vector<scene::SlopeMapEntry> Parser::parse_slope_map_body() {
    if (auto m = declared_map("slope_map")) return m->slopes;
    std::vector<scene::SlopeMapEntry> map;
    parse_map_entries("slope_map", false, [&](double v) {
        Num hs = parse_num(2);
        map.push_back({v, hs.v[0], hs.v[1]});
    });
    return map;
}

std::vector<scene::TextureMapEntry> Parser::parse_texture_map_body(bool average) {
    if (auto m = declared_map("texture_map")) return m->textures;
    std::vector<scene::TextureMapEntry> map;
    parse_map_entries("texture_map", average, [&](double v) {
        scene::Texture t = parse_texture_body();
        map.push_back({v, {t}});
    });
    return map;
}

Value Parser::parse_map_rvalue(const std::string& w) {
    BlendMapValue m;
    m.keyword = w == "colour_map" ? "color_map" : w;
    expect_open(w.c_str());
    FileLoc o = loc();
    if (m.keyword == "color_map") m.colors = parse_color_map_body();
    else if (w == "pigment_map") m.pigments = parse_pigment_map_body(false);
    else if (w == "normal_map") m.normals = parse_normal_map_body(false);
    else if (w == "slope_map") m.slopes = parse_slope_map_body();
    else m.textures = parse_texture_map_body(false);
    expect_close(w.c_str(), o);
    return m;
}

// ---------------------------------------------------------------- pigment

void Parser::parse_pigment_body(scene::Pigment& p) {
    bool first = true;
    if (!p.loc.valid()) p.loc = loc();
    for (;; first = false) {
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
            } else if (w == "color_map" || w == "colour_map") {
                if (takes_no_map(p.kind) || p.kind == PatternKind::Average)
                    fail("cannot use " + w + " with the '" + pattern_name(p.kind) + "' pattern");
                expect_open(w.c_str());
                FileLoc o = loc();
                p.color_map = parse_color_map_body();
                p.pigment_map.clear();
                expect_close(w.c_str(), o);
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

void Parser::parse_normal_body(scene::Normal& n) {
    bool first = true;
    if (!n.loc.valid()) n.loc = loc();
    for (;; first = false) {
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
            if (w == "density_file" && accept("interpolate")) parse_float();
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

scene::Texture Parser::parse_texture_body() {
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
    if (tex.kind != PatternKind::Plain && block_count(tex.kind) == 0 && tex.texture_map.empty())
        fail("a patterned texture needs a texture_map");
    if (uv_plain) {
        scene::Texture& top = top_layer(tex);
        top.pigment.uv_mapping = true;
        top.normal.uv_mapping = true;
    }
    return tex;
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
