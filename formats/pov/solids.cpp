// POV-Ray's quadric, polygon, prism, lathe, sor, superellipsoid, blob, height_field,
// poly/cubic/quartic/polynomial, julia_fractal, bicubic_patch and sphere_sweep bodies, with
// POV-Ray's checks on point counts and order (reference manual 3.4.1 "Finite Solid Primitives",
// 3.4.3 "Finite Patch Primitives", 3.4.4 "Infinite Solid Primitives").
#include "formats/pov/solids.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <unordered_set>

#include "formats/pov/unsupported.h"

namespace glint::pov {

namespace {

constexpr double kEps = 1e-10;  // POV-Ray's EPSILON for "same point" tests

Vec2 parse_uv(Parser& p) {
    Num n = p.parse_num(2);
    return {n.v[0], n.v[1]};
}

// `N, p1, p2, ...` with at least `min` points (message names the object).
int parse_count(Parser& p, int min, const std::string& too_few) {
    p.peek();
    FileLoc at = p.loc();
    double v = p.parse_float();
    // Checked as a double first: casting 1e19 or NaN to int is undefined (found by fuzz_pov).
    if (!(v < 10000001)) p.fail_at(at, "point count is too large (at most 10000000)");
    if (v < min) p.fail_at(at, too_few);
    int n = static_cast<int>(v);
    if (n < min) p.fail_at(at, too_few);
    return n;
}

bool spline_keyword(Parser& p, scene::SplineType* t) {
    if (p.accept("linear_spline")) *t = scene::SplineType::Linear;
    else if (p.accept("quadratic_spline")) *t = scene::SplineType::Quadratic;
    else if (p.accept("cubic_spline")) *t = scene::SplineType::Cubic;
    else if (p.accept("bezier_spline")) *t = scene::SplineType::Bezier;
    else return false;
    return true;
}

scene::Quadric parse_quadric(Parser& p) {
    scene::Quadric q;
    q.square = p.parse_vector();
    p.skip_comma();
    q.mixed = p.parse_vector();
    p.skip_comma();
    q.linear = p.parse_vector();
    p.skip_comma();
    q.constant = p.parse_float();
    return q;
}

scene::Polygon parse_polygon(Parser& p, const FileLoc& kw) {
    scene::Polygon s;
    int n = parse_count(p, 3, "polygon needs at least 3 points");
    for (int i = 0; i < n; ++i) {
        p.skip_comma();
        s.points.push_back(p.parse_vector());
    }
    // Sub-polygons close on their first point; close an open list (POV-Ray warns too).
    Vec3 first = s.points[0];
    bool closed = false;
    for (int i = 1; i < n; ++i) {
        closed = false;
        Vec3 d = abs(first - s.points[i]);
        if (d.x < kEps && d.y < kEps && d.z < kEps) {
            s.points[i] = first;
            ++i;
            if (i < n) first = s.points[i];
            closed = true;
        }
    }
    if (!closed) {
        p.diag.warning(kw, "polygon not closed: closing it");
        s.points.push_back(first);
    }
    return s;
}

scene::Prism parse_prism(Parser& p, const FileLoc& kw) {
    using scene::SplineType;
    scene::Prism s;
    for (;;) {
        if (spline_keyword(p, &s.spline)) continue;
        if (p.accept("linear_sweep")) s.conic = false;
        else if (p.accept("conic_sweep")) s.conic = true;
        else break;
    }
    s.height1 = p.parse_float();
    p.skip_comma();
    s.height2 = p.parse_float();
    p.skip_comma();
    if (s.height1 > s.height2) std::swap(s.height1, s.height2);
    p.peek();
    FileLoc at = p.loc();
    int n = to_int(p.parse_float());
    switch (s.spline) {
        case SplineType::Linear:
            if (n < 3) p.fail_at(at, "prism needs at least 3 points");
            break;
        case SplineType::Quadratic:
            if (n < 5) p.fail_at(at, "prism with quadratic_spline needs at least 5 points");
            break;
        case SplineType::Cubic:
            if (n < 6) p.fail_at(at, "prism with cubic_spline needs at least 6 points");
            break;
        case SplineType::Bezier:
            if (n < 4 || n % 4 != 0)
                p.fail_at(at, "prism with bezier_spline needs 4 points per segment");
            break;
    }
    for (int i = 0; i < n; ++i) {
        p.skip_comma();
        s.points.push_back(parse_uv(p));
    }
    if (p.accept("open")) s.open = true;
    if (s.spline == SplineType::Quadratic || s.spline == SplineType::Cubic) {
        // Compute_Prism's walk: a segment needs its control points after each closed outline.
        const int span = s.spline == SplineType::Quadratic ? 3 : 4;
        const int skip = s.spline == SplineType::Quadratic ? 2 : 3;
        Vec2 first = s.points[1];
        for (int i = 0; i < n - 1; ++i) {
            if (i + span - 1 >= n) p.fail_at(at, "too few points in prism (an outline is not "
                                                 "closed or its control points are missing)");
            const Vec2& end = s.points[i + 2];
            if (std::fabs(end.x - first.x) < kEps && std::fabs(end.y - first.y) < kEps) {
                i += skip;
                if (i + 2 < n) first = s.points[i + 2];
            }
        }
    }
    if (s.spline == SplineType::Linear) {
        // An open outline is closed back to the start of its last sub-outline.
        Vec2 first = s.points[0];
        bool closed = false;
        for (int i = 1; i < n; ++i) {
            closed = false;
            if (std::fabs(first.x - s.points[i].x) < kEps &&
                std::fabs(first.y - s.points[i].y) < kEps) {
                ++i;
                if (i < n) first = s.points[i];
                closed = true;
            }
        }
        if (!closed) {
            p.diag.warning(kw, "linear prism not closed: closing it");
            s.points.push_back(first);
        }
    }
    return s;
}

scene::Lathe parse_lathe(Parser& p) {
    using scene::SplineType;
    scene::Lathe s;
    spline_keyword(p, &s.spline);
    p.peek();
    FileLoc at = p.loc();
    int n = to_int(p.parse_float());
    switch (s.spline) {
        case SplineType::Linear:
            if (n < 2) p.fail_at(at, "lathe needs at least 2 points");
            break;
        case SplineType::Quadratic:
            if (n < 3) p.fail_at(at, "lathe with quadratic_spline needs at least 3 points");
            break;
        case SplineType::Cubic:
            if (n < 4) p.fail_at(at, "lathe with cubic_spline needs at least 4 points");
            break;
        case SplineType::Bezier:
            if (n < 4 || n % 4 != 0)
                p.fail_at(at, "lathe with bezier_spline needs 4 points per segment");
            break;
    }
    for (int i = 0; i < n; ++i) {
        p.skip_comma();
        p.peek();
        FileLoc pl = p.loc();
        Vec2 v = parse_uv(p);
        if (i > 0 && i < n - 1 && v.x < 0)
            p.fail_at(pl, "lathe point " + std::to_string(i + 1) + " has a negative radius");
        s.points.push_back(v);
    }
    return s;
}

scene::Sor parse_sor(Parser& p) {
    scene::Sor s;
    int n = parse_count(p, 4, "sor needs at least 4 points");
    for (int i = 0; i < n; ++i) {
        p.skip_comma();
        p.peek();
        FileLoc pl = p.loc();
        Vec2 v = parse_uv(p);
        if (v.x < 0)
            p.fail_at(pl, "sor point " + std::to_string(i + 1) + " has a negative radius");
        if (i > 1 && i < n - 1 && v.y <= s.points.back().y)
            p.fail_at(pl, "sor point " + std::to_string(i + 1) +
                              " is not higher than the point before it");
        s.points.push_back(v);
    }
    if (p.accept("open")) s.open = true;
    return s;
}

// sphere_sweep { SPLINE N, <centre>, radius, ... [tolerance T] } (parse.cpp
// Parse_Sphere_Sweep). A radius is read without comparisons, so that `0.5 <1, 0, 0>` is a radius
// followed by the next centre, as for a point count.
scene::SphereSweep parse_sphere_sweep(Parser& p) {
    using scene::SweepSpline;
    scene::SphereSweep s;
    p.peek();
    FileLoc at = p.loc();
    const char* spline = nullptr;
    if (p.accept("linear_spline")) s.spline = SweepSpline::Linear, spline = "linear_spline";
    else if (p.accept("b_spline")) s.spline = SweepSpline::BSpline, spline = "b_spline";
    else if (p.accept("cubic_spline")) s.spline = SweepSpline::Cubic, spline = "cubic_spline";
    else p.fail_at(at, "sphere_sweep needs linear_spline, b_spline or cubic_spline first");
    p.skip_comma();
    // Each cubic piece reads four consecutive spheres; a line needs two.
    const int least = s.spline == SweepSpline::Linear ? 2 : 4;
    int n = parse_count(p, least, std::string("sphere_sweep with ") + spline + " needs at least " +
                                      std::to_string(least) + " spheres");
    for (int i = 0; i < n; ++i) {
        scene::Sphere c;
        p.skip_comma();
        c.center = p.parse_vector();
        p.skip_comma();
        p.peek();
        FileLoc rl = p.loc();
        c.radius = p.parse_float();
        if (c.radius < 0)
            p.fail_at(rl, "sphere_sweep sphere " + std::to_string(i + 1) +
                              " has a negative radius");
        s.spheres.push_back(c);
    }
    if (p.accept("tolerance")) {
        p.peek();
        FileLoc tl = p.loc();
        s.tolerance = p.parse_float();
        if (!(s.tolerance >= 0)) p.fail_at(tl, "sphere_sweep tolerance must not be negative");
    }
    return s;
}

scene::Superellipsoid parse_superellipsoid(Parser& p) {
    p.peek();
    FileLoc at = p.loc();
    Vec2 v = parse_uv(p);
    if (!(v.x > 0) || !(v.y > 0)) p.fail_at(at, "superellipsoid exponents <e, n> must be positive");
    return {v.x, v.y};
}

// julia_fractal { <c> keywords } (parse.cpp Parse_Julia_Fractal): the keywords in any order,
// the last of each kind winning.
scene::JuliaFractal parse_julia_fractal(Parser& p) {
    using F = scene::JuliaFunction;
    static const std::pair<const char*, F> kFunctions[] = {
        {"exp", F::Exp},     {"ln", F::Ln},       {"sin", F::Sin},     {"asin", F::Asin},
        {"cos", F::Cos},     {"acos", F::Acos},   {"tan", F::Tan},     {"atan", F::Atan},
        {"sinh", F::Sinh},   {"asinh", F::Asinh}, {"cosh", F::Cosh},   {"acosh", F::Acosh},
        {"tanh", F::Tanh},   {"atanh", F::Atanh}, {"sqr", F::Sqr},     {"cube", F::Cube},
        {"reciprocal", F::Reciprocal}};
    scene::JuliaFractal s;
    Num c = p.parse_num(4);
    for (int i = 0; i < 4; ++i) s.c[i] = c.v[i];
    FileLoc function_at;
    for (;;) {
        p.peek();
        FileLoc at = p.loc();
        if (p.accept("max_iteration")) {
            double v = std::floor(p.parse_float());
            if (!(v < 1e7)) p.fail_at(at, "max_iteration is too large (at most 10000000)");
            s.max_iteration = v < 1 ? 1 : static_cast<int>(v);
        } else if (p.accept("slice")) {
            Num n = p.parse_num(4);
            p.skip_comma();
            s.slice_distance = p.parse_float();
            double len2 = 0;
            for (int i = 0; i < 4; ++i) len2 += n.v[i] * n.v[i];
            if (std::fabs(len2) < kEps) p.fail_at(at, "julia_fractal slice vector is zero");
            if (std::fabs(n.v[3]) < kEps) p.fail_at(at, "julia_fractal slice t component is zero");
            for (int i = 0; i < 4; ++i) s.slice[i] = n.v[i] / std::sqrt(len2);
        } else if (p.accept("precision")) {
            s.precision = std::max(1.0, p.parse_float());
        } else if (p.accept("quaternion")) {
            s.algebra = scene::JuliaAlgebra::Quaternion;
        } else if (p.accept("hypercomplex")) {
            s.algebra = scene::JuliaAlgebra::Hypercomplex;
        } else if (p.accept("pwr")) {
            s.function = F::Pwr;
            function_at = at;
            p.expect("(", "after pwr");
            s.exponent.x = p.parse_float();
            p.skip_comma();
            s.exponent.y = p.parse_float();
            p.expect(")", "after pwr's exponent");
        } else {
            bool found = false;
            for (const auto& [name, f] : kFunctions)
                if (p.accept(name)) {
                    s.function = f;
                    function_at = at;
                    found = true;
                    break;
                }
            if (!found) break;
        }
    }
    if (s.algebra == scene::JuliaAlgebra::Quaternion && s.function != F::Sqr &&
        s.function != F::Cube)
        p.fail_at(function_at, "julia_fractal: quaternion supports only sqr and cube");
    return s;
}

// bicubic_patch { type T flatness F u_steps U v_steps V [uv_vectors 4 x <u,v>] 16 points }
// (parse.cpp Parse_Bicubic_Patch); a leading number starts the old positional form. A number
// right before the first point ends there (`u_steps 8 <0, 0, 2>` compares nothing).
scene::BicubicPatch parse_bicubic_patch(Parser& p, const FileLoc& kw) {
    scene::BicubicPatch s;
    s.type = -1;
    auto steps = [&](int* out) {
        p.peek();
        FileLoc at = p.loc();
        double v = p.parse_float();
        if (!(v > -1e6 && v < 1e6)) p.fail_at(at, "bicubic_patch steps out of range");
        *out = static_cast<int>(v);
    };
    for (;;) {
        const Token& t = p.peek();
        if (t.kind == TokKind::Number || t.is("(") || t.is("-") || t.is("+")) {
            p.diag.warning(p.loc(), "should use keywords for bicubic parameters");
            s.type = static_cast<int>(p.parse_float());
            s.flatness = s.type == 2 || s.type == 3 ? p.parse_float() : 0.1;
            steps(&s.u_steps);
            steps(&s.v_steps);
            break;
        }
        if (p.accept("type")) {
            s.type = static_cast<int>(p.parse_float());
        } else if (p.accept("flatness")) {
            s.flatness = p.parse_float();
        } else if (p.accept("u_steps")) {
            steps(&s.u_steps);
        } else if (p.accept("v_steps")) {
            steps(&s.v_steps);
        } else if (p.accept("accuracy")) {
            p.parse_float();  // type 0's old per-ray accuracy: no effect in 3.7
        } else if (p.accept("uv_vectors")) {
            for (int i = 0; i < 4; ++i) {
                if (i > 0) p.skip_comma();
                s.uv[i] = parse_uv(p);
            }
            break;
        } else {
            break;
        }
    }
    if (s.type > 1) {
        p.diag.warning(kw, "bicubic_patch type no longer supported: using type 1");
        s.type = 1;
    }
    if (s.type < 0) p.fail_at(kw, "undefined bicubic_patch type");
    p.skip_comma();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            if (i + j > 0) p.skip_comma();
            s.points[i][j] = p.parse_vector();
        }
    return s;
}

// Component modifiers (Parse_Blob_Element_Mods): transforms, and the component's own texture,
// which moves with the transforms after it. The texture becomes a material of its own; only
// its texture is used (the blob's material keeps the interior).
void parse_component_mods(Parser& p, scene::BlobComponent& c) {
    std::optional<scene::Texture> tex;
    for (;;) {
        Transform t;
        if (p.parse_transform_item(t)) {
            c.transform = c.transform.then(t);
            if (tex) transform_texture(*tex, t);
            continue;
        }
        const Token& tok = p.peek();
        if (tok.is("texture") || tok.is("pigment") || tok.is("normal") || tok.is("finish")) {
            std::string what = tok.text;
            p.next();
            FileLoc at = p.loc();
            p.expect_open(what.c_str());
            FileLoc lo = p.loc();
            if (what == "texture") {
                scene::Texture body = p.parse_texture_body();
                if (tex) layer_texture(*tex, body, at);  // Link_Textures: a layer on top
                else tex = body;
            } else {
                // A pigment, normal or finish edits the texture, starting from the default
                // one (over a patterned texture: a new default layer on top).
                if (!tex) {
                    tex = p.default_texture_;
                    tex->loc = at;
                } else if (tex->kind != scene::PatternKind::Plain) {
                    scene::Texture top = p.default_texture_;
                    top.loc = at;
                    layer_texture(*tex, top, at);
                }
                if (what == "pigment") p.parse_pigment_body(tex->pigment);
                else if (what == "normal") p.parse_normal_body(tex->normal);
                else p.parse_finish_body(tex->finish);
            }
            p.expect_close(what.c_str(), lo);
            continue;
        }
        break;
    }
    if (tex) c.material = p.add_material(*tex, scene::Interior{}, tex->loc);
}

scene::Blob parse_blob(Parser& p, const FileLoc& kw) {
    scene::Blob b;
    for (;;) {
        if (p.accept("threshold")) {
            b.threshold = p.parse_float();
        } else if (p.accept("component")) {
            scene::BlobComponent c;
            c.strength = p.parse_float();
            p.skip_comma();
            c.radius = p.parse_float();
            p.skip_comma();
            c.center = p.parse_vector();
            b.components.push_back(c);
        } else if (p.accept("sphere")) {
            p.expect_open("sphere");
            FileLoc lo = p.loc();
            scene::BlobComponent c;
            c.center = p.parse_vector();
            p.skip_comma();
            c.radius = p.parse_float();
            p.skip_comma();
            p.accept("strength");
            c.strength = p.parse_float();
            parse_component_mods(p, c);
            p.expect_close("sphere", lo);
            b.components.push_back(c);
        } else if (p.accept("cylinder")) {
            FileLoc at = p.loc();
            p.expect_open("cylinder");
            FileLoc lo = p.loc();
            scene::BlobComponent c;
            c.cylinder = true;
            c.center = p.parse_vector();
            p.skip_comma();
            c.apex = p.parse_vector();
            p.skip_comma();
            c.radius = p.parse_float();
            p.skip_comma();
            p.accept("strength");
            c.strength = p.parse_float();
            if (length(c.apex - c.center) < kEps)
                p.fail_at(at, "degenerate cylindrical component in blob (its ends coincide)");
            parse_component_mods(p, c);
            p.expect_close("cylinder", lo);
            b.components.push_back(c);
        } else {
            break;
        }
    }
    if (b.components.empty()) p.fail_at(kw, "blob needs at least one component");
    return b;
}

// A float converted to a 16-bit integer without a range check, as POV-Ray stores function
// values into its 16-bit images: on x86-64 the value is truncated to 32 bits (out of range and
// NaN give 0x80000000) and the low 16 bits kept, so 1.5 wraps around to 32766.
uint16_t unchecked_u16(float v) {
    if (!(v > -2147483648.0f && v < 2147483648.0f)) return 0;
    return static_cast<uint16_t>(static_cast<uint32_t>(static_cast<int32_t>(v)));
}

// POV-Ray's Make_Pattern_Image and image_height_at (parstxtr.cpp, imageutil.cpp): a scalar
// function fills a 16-bit grey image, a pigment function a 16-bit RGBA one whose grey is the
// height. Image row i is the function at y = i / (H - 1) and lands at z = (H - 1 - i) / (H - 1).
void evaluate_height_grid(Parser& p, int fn, scene::HeightField* h) {
    const scene::Function& f = p.scene.functions[static_cast<size_t>(fn)];
    const scene::FunctionEnv outer = p.function_env();
    scene::FunctionEnv env = outer;
    env.pattern = p.options.pattern_hook;
    env.user = &outer;
    const bool pigment = f.kind == scene::FunctionKind::Pigment;
    const int w = h->grid_w, rows = h->grid_h;
    h->heights.assign(static_cast<size_t>(w) * rows, 0);
    for (int i = 0; i < rows; ++i) {
        const double y = static_cast<double>(i) / (static_cast<float>(rows) - 1.0f);
        uint16_t* out = &h->heights[static_cast<size_t>(rows - 1 - i) * w];
        for (int j = 0; j < w; ++j) {
            const double args[3] = {static_cast<double>(j) / (static_cast<float>(w) - 1.0f), y, 0};
            if (!pigment) {
                float v = static_cast<float>(scene::evaluate_function(env, fn, args, 3));
                float grey = static_cast<float>(unchecked_u16(v * 65535.0f)) / 65535.0f;
                out[j] = static_cast<uint16_t>(grey * 65535.0f);
                continue;
            }
            double c[5] = {0, 0, 0, 0, 0};
            scene::evaluate_function_vector(env, fn, args, 3, c);
            double stored[3];
            for (int k = 0; k < 3; ++k)
                stored[k] = static_cast<float>(
                                unchecked_u16(static_cast<float>(c[k]) * 65535.0f)) /
                            65535.0f;
            double grey = 0.297 * stored[0] + 0.589 * stored[1] + 0.114 * stored[2];
            out[j] = static_cast<uint16_t>(std::clamp(grey * 65535.0f, 0.0, 65535.0));
        }
    }
}

// `function W, H { body }` after height_field's `function`. Empty result: left out.
bool parse_height_function(Parser& p, scene::HeightField* h, std::string* left_out) {
    p.peek();
    FileLoc at = p.loc();
    const double w = p.parse_float();
    p.skip_comma();
    const double rows = p.parse_float();
    if (!p.peek().is_symbol('{')) p.fail("expected '{' after the height_field function's size");
    const int fn = p.parse_function_definition();
    if (!(w + 0.5 >= 2 && rows + 0.5 >= 2 && (w + 0.5) * (rows + 0.5) <= 1 << 26))
        p.fail_at(at, "height_field function size must be at least 2 x 2 and at most 2^26 "
                      "points");
    h->grid_w = static_cast<int>(w + 0.5);
    h->grid_h = static_cast<int>(rows + 0.5);
    const scene::Function& f = p.scene.functions[static_cast<size_t>(fn)];
    if (f.kind == scene::FunctionKind::Transform || f.kind == scene::FunctionKind::Spline)
        p.fail_at(at, "unsupported function type in a height_field function (a pigment or a "
                      "scalar function is needed)");
    if ((f.kind == scene::FunctionKind::Pattern || f.kind == scene::FunctionKind::Pigment) &&
        !p.options.pattern_hook) {
        *left_out = "height_field from a pattern or pigment function here";
        warn_unsupported(p, *left_out, at, "the object is left out");
        return false;
    }
    evaluate_height_grid(p, fn, h);
    return true;
}

scene::HeightField parse_height_field(Parser& p, std::string* left_out) {
    static const std::unordered_set<std::string> kTypes = {
        "gif", "tga", "iff", "pgm", "ppm", "png", "jpeg", "tiff", "sys", "exr", "hdr", "pot"};
    scene::HeightField h;
    const Token& t = p.peek();
    bool body = true;
    if (t.is("function") && !p.lookup(t.text)) {
        p.next();
        body = parse_height_function(p, &h, left_out);
        if (!body) h = scene::HeightField{};
    } else {
        if (t.kind == TokKind::Word && kTypes.count(t.text) && !p.lookup(t.text)) {
            h.pot = t.is("pot");
            p.next();
        }
        p.peek();
        h.file_loc = p.loc();
        h.file = p.parse_string();
        h.resolved_path = p.resolve_file(h.file, h.file_loc);
    }
    for (;;) {
        if (p.accept("water_level")) h.water_level = p.parse_float();
        else if (p.accept("smooth")) h.smooth = true;
        else break;
    }
    return h;
}

// POV-Ray's coefficient order: x power descending, then y, then z.
int term_index(int order, int i, int j, int k) {
    int idx = 0;
    for (int a = order; a >= 0; --a)
        for (int b = order - a; b >= 0; --b)
            for (int c = order - a - b; c >= 0; --c) {
                if (a == i && b == j && c == k) return idx;
                ++idx;
            }
    return -1;
}

scene::Poly parse_poly(Parser& p, const std::string& w) {
    scene::Poly s;
    if (w == "cubic") s.order = 3;
    else if (w == "quartic") s.order = 4;
    else {
        p.peek();
        FileLoc at = p.loc();
        // `poly { 4 <...> }` (no comma, as in POV-Ray's primitiv.pov): a literal order right
        // before '<' is not the start of a comparison.
        s.order = to_int(p.parse_float());
        p.skip_comma();
        if (s.order < 2 || s.order > 35)
            p.fail_at(at, "order of " + w + " is out of range (2 to 35)");
    }
    int n = (s.order + 1) * (s.order + 2) * (s.order + 3) / 6;
    s.coefficients.assign(n, 0.0);
    if (w == "polynomial") {
        // xyz(i, j, k): value, ...
        while (p.accept("xyz")) {
            p.expect("(", "after xyz");
            int i = to_int(p.parse_float());
            p.skip_comma();
            int j = to_int(p.parse_float());
            p.skip_comma();
            int k = to_int(p.parse_float());
            p.expect(")", "after the xyz powers");
            FileLoc at = p.loc();
            p.expect(":", "after xyz(...)");
            double v = p.parse_float();
            int idx = i >= 0 && j >= 0 && k >= 0 ? term_index(s.order, i, j, k) : -1;
            if (idx < 0) p.fail_at(at, "coefficient of polynomial is out of range");
            s.coefficients[idx] = v;
            p.skip_comma();
        }
        return s;
    }
    p.peek();
    FileLoc at = p.loc();
    p.expect("<", ("before the " + w + " coefficients").c_str());
    for (int i = 0; i < n; ++i) {
        if (i > 0) p.skip_comma();
        if (p.peek().is(">"))
            p.fail_at(at, w + " of order " + std::to_string(s.order) + " needs " +
                              std::to_string(n) + " coefficients, got " + std::to_string(i));
        s.coefficients[i] = p.parse_float_in_angle_brackets();
    }
    p.expect(">", ("after the " + std::to_string(n) + " " + w + " coefficients").c_str());
    return s;
}

}  // namespace

bool is_solid_keyword(const std::string& w) {
    static const std::unordered_set<std::string> k = {
        "quadric", "polygon", "prism", "lathe", "sor", "superellipsoid", "blob", "height_field",
        "poly", "cubic", "quartic", "polynomial", "julia_fractal", "bicubic_patch",
        "isosurface", "sphere_sweep", "parametric"};
    return k.count(w) > 0;
}

void parse_solid_body(Parser& p, const std::string& w, const FileLoc& kw, scene::Shape* out,
                      std::string* left_out) {
    if (w == "quadric") *out = parse_quadric(p);
    else if (w == "polygon") *out = parse_polygon(p, kw);
    else if (w == "prism") *out = parse_prism(p, kw);
    else if (w == "lathe") *out = parse_lathe(p);
    else if (w == "sor") *out = parse_sor(p);
    else if (w == "superellipsoid") *out = parse_superellipsoid(p);
    else if (w == "blob") *out = parse_blob(p, kw);
    else if (w == "height_field") *out = parse_height_field(p, left_out);
    else if (w == "julia_fractal") *out = parse_julia_fractal(p);
    else if (w == "bicubic_patch") *out = parse_bicubic_patch(p, kw);
    else if (w == "isosurface") *out = parse_isosurface(p, kw);
    else if (w == "sphere_sweep") *out = parse_sphere_sweep(p);
    else if (w == "parametric") *out = parse_parametric(p, kw);
    else *out = parse_poly(p, w);
}

}  // namespace glint::pov
