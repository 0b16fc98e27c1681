// Helpers for tests that render a POV-Ray scene written in the test: the classic renderer's
// image at a small size.
#pragma once

#include <string>

#include "core/log.h"
#include "render/render.h"
#include "unit/pov_test_util.h"

namespace glint::test {

inline Image render_pov(const std::string& text, int width = 40, int height = 40) {
    render::RenderOptions o;
    o.width = width;
    o.height = height;
    Diagnostics diag;
    return render::render(pov::testing::parse(text), o, diag).image;
}

}  // namespace glint::test
