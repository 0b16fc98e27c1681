// POV-Ray's light_source { projected_through { OBJECT } }: the light reaches a point only
// along a ray that meets the object, only what lies before the object shadows it, the
// light's later transforms move the object, shadowless lights obey it too, and one per light.
#include <gtest/gtest.h>

#include <string>

#include "core/log.h"
#include "render/render.h"
#include "unit/pov_test_util.h"
#include "unit/render_test_util.h"

namespace glint::render {
namespace {

Image render_text(const std::string& text) { return test::render_pov(text); }

// The floor y = 0 over [-4, 4]^2 seen from above; a light straight above at height 10.
std::string floor_scene(const std::string& light_items, const std::string& more = "") {
    return "#version 3.7;\n"
           "camera { orthographic location <0, 20, 0> look_at 0 right 8*x up 8*z }\n"
           "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
           "light_source { <0, 10, 0> rgb 1 " +
           light_items + " }\n" + more;
}

TEST(ProjectedThrough, LightPassesOnlyThroughTheObject) {
    // A disc of radius 1 at height 5 halves the cone: on the floor, the lit spot has radius 2.
    const Image img =
        render_text(floor_scene("projected_through { sphere { <0, 5, 0>, 1 } }"));
    EXPECT_GT(img.pixel(20, 20)[0], 0.5f);  // the centre (x = 0.1)
    EXPECT_GT(img.pixel(28, 20)[0], 0.5f);  // x = 1.7: inside the spot
    EXPECT_EQ(img.pixel(35, 20)[0], 0.0f);  // x = 3.1: outside it
    // Without it the whole floor is lit.
    EXPECT_GT(render_text(floor_scene("")).pixel(35, 20)[0], 0.5f);
}

TEST(ProjectedThrough, OnlyWhatLiesBeforeTheObjectShadows) {
    // A blocker between the object and the light casts no shadow; one below the object does.
    // The floor at x = 1.1 (pixel 25) lies in either blocker's shadow (beside them in view).
    const std::string object = "projected_through { sphere { <0, 5, 0>, 1.5 } }";
    const Image above = render_text(floor_scene(object, "sphere { <0, 8, 0>, 0.5 }\n"));
    EXPECT_GT(above.pixel(25, 20)[0], 0.5f);
    const Image below = render_text(floor_scene(object, "sphere { <0, 2, 0>, 1 }\n"));
    EXPECT_EQ(below.pixel(25, 20)[0], 0.0f);
    EXPECT_GT(below.pixel(30, 20)[0], 0.5f);  // x = 2.1: past the shadow, inside the spot
}

TEST(ProjectedThrough, MovesWithTheLightAndBindsShadowlessLights) {
    // Declared at the origin, the light moved up by 10 takes the object to height 5.
    const std::string moved =
        "#version 3.7;\n"
        "camera { orthographic location <0, 20, 0> look_at 0 right 8*x up 8*z }\n"
        "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
        "light_source { 0 rgb 1 projected_through { sphere { <0, -5, 0>, 1 } } "
        "translate 10*y SHADOWLESS }\n";
    for (const std::string flag : {"", "shadowless"}) {
        std::string text = moved;
        text.replace(text.find("SHADOWLESS"), 10, flag);
        const Image img = render_text(text);
        EXPECT_GT(img.pixel(20, 20)[0], 0.5f) << flag;
        EXPECT_EQ(img.pixel(35, 20)[0], 0.0f) << flag;
    }
}

TEST(ProjectedThrough, OnePerLight) {
    EXPECT_NE(pov::testing::error_of("light_source { 0 rgb 1 projected_through { sphere { 0, 1 } } "
                                     "projected_through { sphere { 0, 1 } } }")
                  .find("only one projected_through is allowed per light_source"),
              std::string::npos);
}

}  // namespace
}  // namespace glint::render
