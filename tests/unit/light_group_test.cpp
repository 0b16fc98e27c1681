// POV-Ray's light_group: how the importer records it in the IR (scene::Light::group,
// scene::Object::light_group and no_global_lights) and what the Whitted integrator makes of
// it: the group's lights light only its objects, global_lights decides whether the scene's
// other lights light them too, and every object still casts shadows from the group's lights.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "core/log.h"
#include "pov_test_util.h"
#include "render/integrators/whitted.h"
#include "render/prepare/prepared_scene.h"

namespace glint::pov::testing {
namespace {

const scene::Object& csg_child(const scene::Object& o, size_t i) {
    return std::get<scene::Csg>(o.shape).children.at(i);
}

TEST(LightGroup, ParsesItsLightsAndObjectsIntoTheIr) {
    scene::Scene s = parse(R"(
        light_source { <0, 10, 0> rgb 1 }
        light_group {
            light_source { <1, 2, 3> rgb 0.5 }
            sphere { 0, 1 }
            union { box { -1, 1 } sphere { 2, 1 } }
            translate x * 10
        }
        sphere { 5, 1 }
    )");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].group, -1);
    const int g = s.lights[1].group;
    EXPECT_GE(g, 0);
    // The group's transform moves its light with it.
    EXPECT_NEAR(s.lights[1].location.x, 11, 1e-12);
    ASSERT_EQ(s.objects.size(), 2u);
    const scene::Object& group = s.objects[0];
    ASSERT_TRUE(std::holds_alternative<scene::Csg>(group.shape));
    EXPECT_EQ(csg_child(group, 0).light_group, g);
    EXPECT_TRUE(csg_child(group, 0).no_global_lights);  // global_lights is off by default
    // Shapes inside CSG in the group get it too.
    EXPECT_EQ(csg_child(csg_child(group, 1), 0).light_group, g);
    EXPECT_TRUE(csg_child(csg_child(group, 1), 1).no_global_lights);
    // The object outside is left alone.
    EXPECT_EQ(s.objects[1].light_group, -1);
    EXPECT_FALSE(s.objects[1].no_global_lights);
}

TEST(LightGroup, GlobalLightsOnKeepsTheSceneLights) {
    scene::Scene s = parse(R"(
        light_group { light_source { 1 rgb 1 } sphere { 0, 1 } global_lights on }
        light_group { light_source { 1 rgb 1 } sphere { 0, 1 } global_lights }
        light_group { light_source { 1 rgb 1 } sphere { 0, 1 } global_lights off }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_FALSE(csg_child(s.objects[0], 0).no_global_lights);
    EXPECT_FALSE(csg_child(s.objects[1], 0).no_global_lights);
    EXPECT_TRUE(csg_child(s.objects[2], 0).no_global_lights);
    // Three groups, three ids.
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_NE(s.lights[0].group, s.lights[1].group);
    EXPECT_NE(s.lights[1].group, s.lights[2].group);
}

TEST(LightGroup, NestedGroupsKeepTheirOwnLightsButTheOuterGlobalSetting) {
    scene::Scene s = parse(R"(
        light_group {
            light_source { 1 rgb 1 }
            light_group { light_source { 2 rgb 1 } sphere { 0, 1 } }
            sphere { 3, 1 }
            global_lights on
        }
    )");
    ASSERT_EQ(s.lights.size(), 2u);
    const int outer = s.lights[0].group, inner = s.lights[1].group;
    EXPECT_NE(inner, outer);
    const scene::Object& o = s.objects.at(0);
    EXPECT_EQ(csg_child(csg_child(o, 0), 0).light_group, inner);
    EXPECT_FALSE(csg_child(csg_child(o, 0), 0).no_global_lights);
    EXPECT_EQ(csg_child(o, 1).light_group, outer);
}

TEST(LightGroup, LightsInsideAUnionInTheGroupStayGlobal) {
    scene::Scene s = parse(R"(
        light_group { union { light_source { 1 rgb 1 } sphere { 0, 1 } } sphere { 3, 1 } }
    )");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].group, -1);
}

TEST(LightGroup, EachCopyOfADeclaredGroupHasItsOwnLights) {
    scene::Scene s = parse(R"(
        #declare G = light_group { light_source { <0, 5, 0> rgb 1 } sphere { 0, 1 } }
        object { G }
        object { G translate x * 10 }
    )");
    ASSERT_EQ(s.lights.size(), 2u);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_NE(s.lights[0].group, s.lights[1].group);
    EXPECT_EQ(csg_child(s.objects[0], 0).light_group, s.lights[0].group);
    EXPECT_EQ(csg_child(s.objects[1], 0).light_group, s.lights[1].group);
    EXPECT_NEAR(s.lights[1].location.x, 10, 1e-12);
}

// POV-Ray's copies clear their light lists, so the group around a copied group lights the
// copy's objects too; a group written out in place keeps only its own lights.
TEST(LightGroup, ACopiedNestedGroupIsLitByTheGroupAroundIt) {
    scene::Scene s = parse(R"(
        #declare Inner = light_group { light_source { 2 rgb 1 } sphere { 0, 1 } }
        light_group {
            light_source { 1 rgb 1 }
            object { Inner }
            light_group { light_source { 3 rgb 1 } sphere { 5, 1 } }
        }
    )");
    ASSERT_EQ(s.lights.size(), 3u);
    const scene::Light& outer = s.lights[0];
    const int copied = s.lights[1].group, in_place = s.lights[2].group;
    ASSERT_EQ(outer.also_groups.size(), 1u);
    EXPECT_EQ(outer.also_groups[0], copied);
    EXPECT_NE(copied, in_place);
    EXPECT_TRUE(s.lights[1].also_groups.empty());
}

TEST(LightGroup, NoWarningAnyMore) {
    Diagnostics diag;
    parse_string("light_group { light_source { 1 rgb 1 } sphere { 0, 1 } }", "test.pov", {},
                 diag);
    for (const Diagnostic& d : diag.all())
        EXPECT_EQ(d.message.find("light_group"), std::string::npos) << d.message;
}

// The radiance seen along +z from z = -5 at height y, in a parsed scene.
Color seen(const scene::Scene& s, double x, double y) {
    render::RenderOptions opts;
    Diagnostics diag;
    auto prepared = render::prepare(s, opts, diag);
    render::Whitted w(*prepared);
    render::Ray r;
    r.origin = Vec3(x, y, -5);
    r.dir = Vec3(0, 0, 1);
    return w.li(r);
}

// Two white boxes facing the camera (their fronts at z = -1), x < 0 inside the group, x > 0
// outside; a light straight in front of each, the left one in the group.
const char* kTwoBoxes = R"(
    #default { finish { ambient 0 diffuse 1 } }
    light_source { <2, 0, -100> rgb 0.25 }
    light_group {
        light_source { <-2, 0, -100> rgb 0.5 }
        box { <-3, -1, -1>, <-1, 1, 1> pigment { rgb 1 } }
        %s
    }
    box { <1, -1, -1>, <3, 1, 1> pigment { rgb 1 } }
)";

scene::Scene two_boxes(const std::string& extra) {
    char text[1024];
    std::snprintf(text, sizeof text, kTwoBoxes, extra.c_str());
    return parse(text);
}

TEST(LightGroup, TheGroupsLightLightsOnlyItsObjects) {
    scene::Scene s = two_boxes("");
    // Inside: only the group's light (0.5); the global one (0.25) is off for it.
    const Color in = seen(s, -2, 0);
    EXPECT_NEAR(in.g, 0.5, 0.01);
    // Outside: only the global light; the group's light does not reach it.
    const Color out = seen(s, 2, 0);
    EXPECT_NEAR(out.g, 0.25, 0.01);
}

TEST(LightGroup, GlobalLightsOnAddsTheSceneLights) {
    scene::Scene s = two_boxes("global_lights on");
    EXPECT_NEAR(seen(s, -2, 0).g, 0.75, 0.01);
    EXPECT_NEAR(seen(s, 2, 0).g, 0.25, 0.01);
}

TEST(LightGroup, ObjectsOutsideTheGroupCastShadowsFromItsLights) {
    // A blocker outside the group between the group's light and its box.
    scene::Scene s = parse(R"(
        #default { finish { ambient 0 diffuse 1 } }
        light_group {
            light_source { <0, 0, -100> rgb 1 }
            box { <-3, -1, -1>, <3, 1, 1> pigment { rgb 1 } }
        }
        box { <1, -1, -50>, <4, 1, -49> pigment { rgb 1 } }
    )");
    EXPECT_NEAR(seen(s, -2, 0).g, 1.0, 0.01);
    EXPECT_NEAR(seen(s, 2, 0).g, 0.0, 1e-9);
}

}  // namespace
}  // namespace glint::pov::testing
