// parametric { function { fx } [,] function { fy } [,] function { fz } <u1, v1> [,] <u2, v2>
// [accuracy F] [max_gradient F] [precompute D [,] [x] [,] [y] [,] [z]]
// [contained_by { box { C1, C2 } | sphere { C, R } }] } (reference manual 3.4.5.1.10; POV-Ray's
// Parse_Parametric: the uv corners sorted per component, POV-Ray's defaults: accuracy 0.001,
// max_gradient 1, the box <-1, -1, -1>, <1, 1, 1>).
#include <algorithm>
#include <utility>

#include "formats/pov/solids.h"

namespace glint::pov {

scene::Parametric parse_parametric(Parser& p, const FileLoc& kw) {
    scene::Parametric s;
    for (int i = 0; i < 3; ++i) {
        if (!p.accept("function"))
            p.fail(std::string("expected the function for ") + "xyz"[i] +
                   " in parametric (function { ... }), got " + p.got(p.peek()));
        s.function[i] = p.parse_function_definition();
        if (i < 2) p.skip_comma();  // none after the third: the uv range follows at once
    }
    Num lo = p.parse_num(2);
    p.skip_comma();
    Num hi = p.parse_num(2);
    s.uv_min = Vec2(std::min(lo.v[0], hi.v[0]), std::min(lo.v[1], hi.v[1]));
    s.uv_max = Vec2(std::max(lo.v[0], hi.v[0]), std::max(lo.v[1], hi.v[1]));
    bool precompute = false;
    FileLoc precompute_at;
    for (;;) {
        FileLoc at;
        if (p.accept("accuracy")) {
            s.accuracy = p.parse_float();
        } else if (p.accept("max_gradient")) {
            s.max_gradient = p.parse_float();
        } else if (p.accept_at("precompute", &at)) {
            precompute_at = at;
            const double depth = p.parse_float();
            s.precompute_depth = static_cast<int>(std::clamp(depth, -1e6, 1e6));
            // POV-Ray looks for x, then y, then z, each after an optional comma.
            p.skip_comma();
            s.precompute[0] = p.accept("x");
            p.skip_comma();
            s.precompute[1] = p.accept("y");
            p.skip_comma();
            s.precompute[2] = p.accept("z");
            precompute = s.precompute[0] || s.precompute[1] || s.precompute[2];
        } else if (p.accept("contained_by")) {
            parse_contained_by(p, &s.container);
        } else {
            break;
        }
    }
    if (!precompute) {
        s.precompute_depth = 0;
    } else if (s.precompute_depth < 1 || s.precompute_depth > 20) {
        // POV-Ray's Precompute_Parametric_Values stops the parse ("invalid depth").
        p.fail_at(precompute_at, "parametric precompute depth must be 1 to 20, got " +
                                     std::to_string(s.precompute_depth));
    }
    // POV-Ray takes any numbers and then never ends its search (accuracy <= 0) or divides by
    // zero (max_gradient 0): an error here.
    if (!(s.accuracy > 0)) p.fail_at(kw, "parametric accuracy must be positive");
    if (!(s.max_gradient > 0)) p.fail_at(kw, "parametric max_gradient must be positive");
    return s;
}

}  // namespace glint::pov
