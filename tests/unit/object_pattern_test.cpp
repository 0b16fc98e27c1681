// POV-Ray's object pattern (PatternKind::Object): the second entry inside the object, the
// first outside, the object in the pattern's own space (it stays put when the texture moves,
// and moves with the pattern's transforms), an identifier or an object statement, and the
// errors POV-Ray gives.
#include <gtest/gtest.h>

#include <string>

#include "core/log.h"
#include "render/render.h"
#include "unit/pov_test_util.h"
#include "unit/render_test_util.h"

namespace glint::render {
namespace {

Image render_text(const std::string& text) { return test::render_pov(text); }

// An orthographic view of the plane z = 0 over [-1, 1]^2, lit by ambient only.
std::string plane_with(const std::string& pigment) {
    return "#version 3.7;\n"
           "camera { orthographic location <0, 0, -5> look_at 0 right 2*x up 2*y }\n"
           "plane { z, 0 pigment { " +
           pigment + " } finish { ambient 1 diffuse 0 } }\n";
}

TEST(ObjectPattern, InsideTakesTheSecondEntry) {
    const Image img = render_text(
        "#declare S = sphere { <0.5, 0, 0>, 0.3 }\n" +
        plane_with("object { S color rgb <1, 0, 0>, color rgb <0, 0, 1> }"));
    // Pixel (30, 20) is at x = 0.525: inside; (10, 20) at x = -0.475: outside.
    EXPECT_FLOAT_EQ(img.pixel(30, 20)[2], 1.0f);
    EXPECT_FLOAT_EQ(img.pixel(30, 20)[0], 0.0f);
    EXPECT_FLOAT_EQ(img.pixel(10, 20)[0], 1.0f);
    EXPECT_FLOAT_EQ(img.pixel(10, 20)[2], 0.0f);
}

TEST(ObjectPattern, MovesWithThePatternNotTheTextureOwner) {
    // The object statement's own transform, then the pigment's translate: the sphere ends up
    // at x = -0.5.
    const Image img = render_text(plane_with(
        "object { sphere { 0, 0.3 translate x } rgb 0, rgb 1 } translate -1.5*x"));
    EXPECT_FLOAT_EQ(img.pixel(10, 20)[1], 1.0f);  // x = -0.475: inside
    EXPECT_FLOAT_EQ(img.pixel(30, 20)[1], 0.0f);
}

TEST(ObjectPattern, ErrorsAsPovRay) {
    using pov::testing::error_of;
    EXPECT_NE(error_of(plane_with("object { 3 rgb 0, rgb 1 }"))
                  .find("object or object identifier expected"),
              std::string::npos);
    EXPECT_NE(error_of("#declare P = pigment { rgb 1 }\n" +
                       plane_with("object { P rgb 0, rgb 1 }"))
                  .find("object or object identifier expected, got a pigment 'P'"),
              std::string::npos);
}

}  // namespace
}  // namespace glint::render
