// isosurface { function { ... } [contained_by { box | sphere }] [threshold F] [accuracy F]
// [max_gradient F] [evaluate P0, P1, P2] [max_trace N | all_intersections] [open] }
// (reference manual 2.4.2.3; POV-Ray's Parse_Isosurface, whose defaults and corrections of bad
// values, with their warnings, this follows).
#include <algorithm>

#include "formats/pov/solids.h"

namespace glint::pov {

void parse_contained_by(Parser& p, scene::Container* c) {
    p.expect_open("contained_by");
    FileLoc opened = p.loc();
    if (p.accept("box")) {
        p.expect_open("box");
        FileLoc lo = p.loc();
        Vec3 a = p.parse_vector();
        p.skip_comma();
        Vec3 b = p.parse_vector();
        p.expect_close("box", lo);
        c->sphere = false;
        c->corner1 = min(a, b);
        c->corner2 = max(a, b);
    } else if (p.accept("sphere")) {
        p.expect_open("sphere");
        FileLoc lo = p.loc();
        c->center = p.parse_vector();
        p.skip_comma();
        c->radius = p.parse_float();
        p.expect_close("sphere", lo);
        c->sphere = true;
    }
    p.expect_close("contained_by", opened);
}

namespace {

constexpr int kMaxTrace = 10;  // POV-Ray's ISOSURFACE_MAXTRACE: what all_intersections asks for

}  // namespace

scene::Isosurface parse_isosurface(Parser& p, const FileLoc& kw) {
    scene::Isosurface s;
    if (!p.accept("function")) p.fail("expected function after isosurface {, got " + p.got(p.peek()));
    s.function = p.parse_function_definition();
    for (;;) {
        if (p.accept("contained_by")) {
            parse_contained_by(p, &s.container);
        } else if (p.accept("threshold")) {
            s.threshold = p.parse_float();
        } else if (p.accept("accuracy")) {
            s.accuracy = p.parse_float();
        } else if (p.accept("max_gradient")) {
            s.max_gradient = p.parse_float();
        } else if (p.accept("max_trace")) {
            // POV-Ray stores it in a short: truncation toward zero.
            s.max_trace = static_cast<int>(std::clamp(p.parse_float(), -1e6, 1e6));
        } else if (p.accept("evaluate")) {
            s.evaluate = true;
            for (int i = 0; i < 3; ++i) {
                if (i > 0) p.skip_comma();
                s.eval[i] = p.parse_float();
            }
        } else if (p.accept("open")) {
            s.open = true;
        } else if (p.accept("all_intersections")) {
            s.max_trace = kMaxTrace;
        } else {
            break;
        }
    }
    if (!(s.accuracy > 0)) {
        p.diag.warning(kw, "isosurface 'accuracy' is not positive: using 0.001 (the default)");
        s.accuracy = 0.001;
    }
    if (!(s.max_gradient > 0)) {
        p.diag.warning(kw, "isosurface 'max_gradient' is not positive: using 1.1 (the default)");
        s.max_gradient = 1.1;
    }
    if (s.max_trace > kMaxTrace) {
        p.diag.warning(kw, "isosurface 'max_trace' exceeds the maximum of 10: using 10");
        s.max_trace = kMaxTrace;
    }
    if (s.max_trace < 1) {
        p.diag.warning(kw, "isosurface 'max_trace' is not positive: using 1 (the default)");
        s.max_trace = 1;
    }
    return s;
}

}  // namespace glint::pov
