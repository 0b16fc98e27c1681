// The grammar every pattern shares (reference manual 3.4.11 "Patterns"; parstxtr.cpp
// Parse_Pattern/Parse_Warp and express.cpp Parse_Blend_Map/Parse_Colour_Map in POV-Ray 3.7): a
// pattern keyword's arguments and the modifiers all patterns take, warps, and the maps. The
// pigment, normal and texture bodies that use them are in patterns.cpp.
//
// Pattern space: a pattern's own `transform` is POV-Ray's leading TRANSFORM_WARP (the most
// recent transforms); `params.warps` are the rest of POV-Ray's warp list in the order they are
// applied to the point. A warp { } block goes in front (it is applied before the transforms
// written earlier), and turbulence written in the pattern modifies or appends a classic
// turbulence warp at the end (Check_Turb). Map and block entries are evaluated in the parent's
// warped pattern space, so their transforms are relative to the parent's.
#include <cmath>

#include "formats/pov/parser_impl.h"
#include "formats/pov/unsupported.h"

namespace glint::pov {

namespace {

using scene::PatternKind;
using scene::WarpKind;

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

}  // namespace

// ---------------------------------------------------------------- shared pattern grammar

// The arguments of a pattern keyword (already read). Block pattern entries are read by the
// caller, which knows what they are (colors, pigments, normals, textures).
void Parser::parse_pattern_arguments(PatternKind kind, scene::PatternParams& pp, bool normal) {
    FileLoc l = loc();
    // mandel, julia and magnet: [the julia constant,] the iterations, POV-Ray's colouring.
    auto fractal_tail = [&](bool julia) {
        if (julia) {
            Num c = parse_num(2);
            pp.julia_param = Vec2(c.v[0], c.v[1]);
            skip_comma();
        }
        pp.iterations = to_int(parse_float());
        pp.interior_type = 0;
        pp.exterior_type = 1;
        pp.interior_factor = pp.exterior_factor = 1;
    };
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
            fractal_tail(kind == PatternKind::Julia);
            pp.fractal_exponent = 2;
            break;
        case PatternKind::Slope:
            parse_slope(pp.slope);
            break;
        case PatternKind::Magnet: {  // magnet 1|2 mandel I | magnet 1|2 julia <c>, I
            FileLoc tl = loc();
            int type = to_int(parse_float());
            if (accept("julia")) {
                pp.magnet_julia = true;
            } else if (!accept("mandel")) {
                fail("expected 'mandel' or 'julia' after the magnet type");
            }
            if (type != 1 && type != 2)
                fail_at(tl, std::string("magnet ") + (pp.magnet_julia ? "julia" : "mandel") +
                                " type must be 1 or 2");
            pp.magnet_type = type;
            fractal_tail(pp.magnet_julia);
            break;
        }
        case PatternKind::Tiling: {  // tiling N, N from 1 to 27 (truncated like POV-Ray's)
            FileLoc tl = loc();
            int n = to_int(parse_float());
            if (n < 1 || n > 27) fail_at(tl, "tiling number must be 1 to 27");
            if (n > 7 && n != 10) {  // render/textures/tiling_pattern.cpp: 1 to 7 and 10
                warn_unsupported(*this, "tiling " + std::to_string(n), tl,
                                 "drawn as tiling 1 (squares)");
            }
            pp.tiling_type = n;
            break;
        }
        case PatternKind::PigmentPattern: {  // pigment_pattern { PIGMENT }
            expect_open("pigment_pattern");
            FileLoc po = loc();
            auto pg = std::make_shared<scene::Pigment>();  // POV-Ray's Create_Pigment: black
            pg->color = scene::ColorFT(Color(0, 0, 0));
            pg->loc = po;
            parse_pigment_body(*pg);
            expect_close("pigment_pattern", po);
            pp.pigment = std::move(pg);
            break;
        }
        case PatternKind::ImagePattern: {  // image_pattern { [type] "file" items }
            expect_open("image_pattern");
            FileLoc io = loc();
            pp.image = scene::ImageMap{};
            pp.image.loc = io;
            pp.image.data = true;  // Parse_Image without gamma correction
            parse_image_map_body(pp.image, nullptr, false, true);
            expect_close("image_pattern", io);
            pp.frequency = 0;  // Parse_Image_Pattern: the values are not reshaped by default
            break;
        }
        case PatternKind::Function:  // function { expression } (functions.cpp)
            pp.function = parse_function_definition();
            break;
        case PatternKind::DensityFile: {  // density_file df3 "file" [interpolate N]
            if (!accept("df3")) fail("expected df3 after density_file, got " + got(next()));
            FileLoc at = loc();
            const std::string name = parse_string();
            pp.density_file = load_df3(name, resolve_file(name, at), at);
            if (accept("interpolate")) pp.density_interpolate = to_int(parse_float());
            break;
        }
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
        case PatternKind::Object: {
            // object { OBJECT [transforms] ENTRY_A, ENTRY_B } (Parse_Bound_Clip): an object
            // statement or identifier; the caller reads the entries, close_object_pattern()
            // the brace.
            expect_open("object");
            object_pattern_open_.push_back(loc());
            PovObject o;
            const Token& t = next();
            if (t.kind == TokKind::Word && lookup(t.text)) {
                const Symbol& s = use_symbol(t);
                auto obj = std::get_if<std::shared_ptr<const PovObject>>(&s.value);
                if (!obj) fail("object or object identifier expected, got " +
                               value_kind_name(s.value) + " '" + t.text + "'");
                o = **obj;
            } else if (!parse_object(t, o)) {
                unget();
                fail("object or object identifier expected, got " + got(peek()));
            }
            for (Transform d; parse_transform_item(d); d = Transform()) apply_transform(o, d);
            scene.pattern_objects.push_back(object_without_materials(o));
            pp.object = static_cast<int>(scene.pattern_objects.size()) - 1;
            break;
        }
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

void Parser::close_object_pattern() {
    if (object_pattern_open_.empty()) return;
    const FileLoc opened = object_pattern_open_.back();
    object_pattern_open_.pop_back();
    expect_close("object", opened);
}

// slope <v> or slope { [point_at] <v> [, lo [, hi]] [altitude <a> [, lo [, hi]]] }, as
// POV-Ray 3.7's parser reads it and prepares it.
void Parser::parse_slope(scene::SlopeParams& s) {
    s = scene::SlopeParams();
    s.vector = Vec3(0, 0, 0);
    // An optional float after an optional comma (Parse_Comma + Allow_Float).
    auto allow_float = [&]() {
        skip_comma();
        return next_is_expression_start() ? parse_float() : 0.0;
    };
    // lo, hi -> lo, hi - lo; an empty range is ignored with POV-Ray's warning.
    auto range = [&](double* lo, double* span, const char* what) {
        FileLoc at = loc();
        *lo = allow_float();
        double hi = allow_float();
        if (hi != 0.0 && hi == *lo) {
            *lo = 0;
            *span = 0;
            diag.warning(at, std::string("zero ") + what + " range, ignoring");
        } else {
            *span = hi - *lo;
        }
    };
    if (peek().is_symbol('{')) {
        expect_open("slope");
        FileLoc opened = loc();
        s.point_at = accept("point_at");
        s.vector = parse_vector();
        range(&s.lo, &s.span, "slope");
        if (accept("altitude")) {
            if (s.point_at)
                fail("'altitude' cannot be used with 'point_at' in the slope pattern");
            s.altitude = parse_vector();
            range(&s.altitude_lo, &s.altitude_span, "gradient");
        }
        expect_close("slope", opened);
    } else {
        s.vector = parse_vector();
    }
    if (s.point_at) {
        s.weight = 1;
        s.altitude_weight = 0;
        return;
    }
    double sl = length(s.vector), al = length(s.altitude);
    if (sl != 0) s.vector = s.vector / sl;
    if (al != 0) s.altitude = s.altitude / al;
    if (sl + al == 0) fail("zero length for both slope and altitude in the slope pattern");
    s.weight = sl / (sl + al);
    s.altitude_weight = 1.0 - s.weight;
    auto base = [](const Vec3& v) {
        for (int i = 0; i < 3; ++i) {
            if (v[i] == 1.0) return i + 1;
            if (v[i] == -1.0) return -(i + 1);
        }
        return 0;
    };
    s.base = base(s.vector);
    s.altitude_base = base(s.altitude);
}

bool Parser::parse_pattern_modifier(const std::string& w, PatternKind kind,
                                    scene::PatternParams& pp, Transform& head) {
    auto only = [&](bool ok, const char* what) {
        if (!ok) fail("'" + w + "' applies only to " + what + " patterns");
    };
    const bool fractal = kind == PatternKind::Mandel || kind == PatternKind::Julia;
    const bool fractal_colouring = fractal || kind == PatternKind::Magnet;
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
    } else if (w == "interpolate") {  // density_file's, also after its other modifiers
        only(kind == PatternKind::DensityFile, "density_file");
        pp.density_interpolate = to_int(parse_float());
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
        only(fractal_colouring, "mandel, julia and magnet");
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

// density_map { [v DENSITY-BODY] ... }: a pigment_map of densities (a colour is a plain one).
std::vector<scene::PigmentMapEntry> Parser::parse_density_map_body() {
    if (auto m = declared_map("density_map")) return m->pigments;
    std::vector<scene::PigmentMapEntry> map;
    parse_map_entries("density_map", false, [&](double v) {
        map.push_back({v, {parse_density_body()}});
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
    else if (w == "density_map") m.pigments = parse_density_map_body();
    else if (w == "normal_map") m.normals = parse_normal_map_body(false);
    else if (w == "slope_map") m.slopes = parse_slope_map_body();
    else m.textures = parse_texture_map_body(false);
    expect_close(w.c_str(), o);
    return m;
}

}  // namespace glint::pov
