// POV-Ray expressions, checked through #declare and the values that reach the IR.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/pov_test_util.h"

namespace glint::pov {
namespace {

using testing::error_of;
using testing::parse;

// Evaluates a float expression by placing it in a sphere radius.
double eval(const std::string& expr, const std::string& prelude = "") {
    auto s = parse(prelude + "\nsphere { 0, " + expr + " }");
    return std::get<scene::Sphere>(s.objects.at(0).shape).radius;
}
Vec3 eval_vec(const std::string& expr, const std::string& prelude = "") {
    auto s = parse(prelude + "\nsphere { " + expr + ", 1 }");
    return std::get<scene::Sphere>(s.objects.at(0).shape).center;
}
scene::ColorFT eval_color(const std::string& expr, const std::string& prelude = "") {
    auto s = parse(prelude + "\nsphere { 0, 1 pigment { " + expr + " } }");
    return s.materials.at(s.objects.at(0).material).texture.pigment.color;
}

TEST(PovExpression, Arithmetic) {
    EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7);
    EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9);
    EXPECT_DOUBLE_EQ(eval("-2 * -3"), 6);
    EXPECT_DOUBLE_EQ(eval("10 / 4"), 2.5);
    EXPECT_DOUBLE_EQ(eval("2 - 3 - 4"), -5);
}

TEST(PovExpression, LogicAndComparison) {
    EXPECT_DOUBLE_EQ(eval("(1 < 2) + 1"), 2);
    EXPECT_DOUBLE_EQ(eval("(2 <= 1) + 1"), 1);
    EXPECT_DOUBLE_EQ(eval("(1 = 1 & 2 != 3) + 1"), 2);
    EXPECT_DOUBLE_EQ(eval("(0 | 0) + 1"), 1);
    EXPECT_DOUBLE_EQ(eval("(!0) + 1"), 2);
    EXPECT_DOUBLE_EQ(eval("(1 > 2 ? 5 : 7)"), 7);
    EXPECT_DOUBLE_EQ(eval("(true ? 5 : 7) + on + yes + off"), 7);
}

// A parameter is an additive expression, as POV-Ray's Parse_Float reads it: `1 <0, 2, 0>` is a
// radius and then a point, and a comparison needs parentheses. #declare and the conditions of
// #if, #while, #switch and #case take the whole grammar (#range's bounds do not).
TEST(PovExpression, ComparisonsOnlyWhereTheGrammarTakesThem) {
    auto s = parse("cone { <0, 0, 0>, 1 <0, 1.5, 0>, 0.25 }");
    const auto& cone = std::get<scene::Cone>(s.objects.at(0).shape);
    EXPECT_DOUBLE_EQ(cone.base_radius, 1);
    EXPECT_EQ(cone.cap, Vec3(0, 1.5, 0));
    EXPECT_DOUBLE_EQ(cone.cap_radius, 0.25);
    EXPECT_DOUBLE_EQ(eval("B + 1", "#declare B = 1 < 2;"), 2);
    EXPECT_DOUBLE_EQ(eval("R", "#declare R = 1; #if (R < 2 & R > 0) #declare R = 3; #end"), 3);
    EXPECT_DOUBLE_EQ(eval("R", "#declare R = 1; #while (R < 4) #declare R = R + 1; #end"), 4);
    EXPECT_DOUBLE_EQ(
        eval("R", "#declare R = 1; #switch (R < 2) #case (R = 1) #declare R = 5; #break #end"),
        5);
}

// POV-Ray 3.7's arrays whose elements are arrays: A[i][j] reads and assigns through them.
TEST(PovExpression, ArraysOfArrays) {
    const std::string a = "#declare A = array[2] { array[2] {0.5, 1}, array[3] {1.5, 2, 2.5} };";
    EXPECT_DOUBLE_EQ(eval("A[1][2]", a), 2.5);
    EXPECT_DOUBLE_EQ(eval("A[0][1] + dimension_size(A[1], 1)", a), 4);
    EXPECT_DOUBLE_EQ(eval("A[1][0]", a + " #declare A[1][0] = 0.75;"), 0.75);
    EXPECT_EQ(error_of(a + "\nsphere { 0, A[1][3] }"),
              "2:18: index 3 is outside the array 'A[1]' (size 3)");
}

TEST(PovExpression, Functions) {
    EXPECT_DOUBLE_EQ(eval("abs(-3)"), 3);
    EXPECT_DOUBLE_EQ(eval("sqrt(16)"), 4);
    EXPECT_DOUBLE_EQ(eval("pow(2, 10)"), 1024);
    EXPECT_DOUBLE_EQ(eval("log(1000)"), 3);  // base 10 in POV-Ray
    EXPECT_DOUBLE_EQ(eval("ln(exp(2))"), 2);
    EXPECT_DOUBLE_EQ(eval("floor(2.7) + ceil(0.2) + int(-2.7)"), 1);
    EXPECT_DOUBLE_EQ(eval("mod(7, 3)"), 1);
    EXPECT_DOUBLE_EQ(eval("min(4, 2, 8) + max(1, 5)"), 7);
    EXPECT_NEAR(eval("degrees(pi)"), 180, 1e-12);
    EXPECT_NEAR(eval("radians(90)"), kPi / 2, 1e-15);
    EXPECT_NEAR(eval("atan2(1, 1)"), kPi / 4, 1e-15);
    EXPECT_NEAR(eval("sin(pi/2) + cos(0)"), 2, 1e-15);
    EXPECT_DOUBLE_EQ(eval("vlength(<3, 4, 0>)"), 5);
    EXPECT_DOUBLE_EQ(eval("vdot(x, <2, 3, 4>)"), 2);
    EXPECT_DOUBLE_EQ(eval("strlen(\"abc\") + val(\"2.5\")"), 5.5);
}

TEST(PovExpression, Vectors) {
    EXPECT_EQ(eval_vec("<1, 2, 3> * 2"), Vec3(2, 4, 6));
    EXPECT_EQ(eval_vec("x + 2*y - z"), Vec3(1, 2, -1));
    EXPECT_EQ(eval_vec("3"), Vec3(3, 3, 3));  // a float promotes to all components
    EXPECT_EQ(eval_vec("vcross(x, y)"), Vec3(0, 0, 1));
    EXPECT_EQ(eval_vec("vnormalize(<0, 3, 0>)"), Vec3(0, 1, 0));
    Vec3 r = eval_vec("vrotate(x, <0, 0, 90>)");
    EXPECT_NEAR(r.x, 0, 1e-12);
    EXPECT_NEAR(r.y, 1, 1e-12);
    EXPECT_DOUBLE_EQ(eval("<1, 2, 3>.y + V.z", "#declare V = <4, 5, 6>;"), 8);
    EXPECT_EQ(eval_vec("<1, (2 > 1), 3>"), Vec3(1, 1, 3)) << "parenthesised comparison";
}

TEST(PovExpression, Colors) {
    auto c = eval_color("rgb <1, 0.5, 0>");
    EXPECT_EQ(c.rgb, Color(1, 0.5, 0));
    c = eval_color("rgbt <1, 1, 1, 0.9>");
    EXPECT_EQ(c.transmit, 0.9);
    EXPECT_EQ(c.filter, 0);
    c = eval_color("rgbf <1, 1, 1, 0.3>");
    EXPECT_EQ(c.filter, 0.3);
    c = eval_color("color red 0.2 green 0.4 blue 0.6 filter 0.1");
    EXPECT_EQ(c.rgb, Color(0.2, 0.4, 0.6));
    EXPECT_EQ(c.filter, 0.1);
    c = eval_color("W * 0.5", "#declare W = rgb 1;");
    EXPECT_EQ(c.rgb, Color(0.5, 0.5, 0.5));
    EXPECT_EQ(c.filter, 0);
    // POV-Ray: a bare float as a pigment color fills all five channels.
    c = eval_color("color 0.5");
    EXPECT_EQ(c.filter, 0.5);
    EXPECT_EQ(c.transmit, 0.5);
    c = eval_color("rgb 0.5");
    EXPECT_EQ(c.transmit, 0);
    c = eval_color("rgb <1,1,1> transmit 0.25");
    EXPECT_EQ(c.transmit, 0.25);
    EXPECT_DOUBLE_EQ(eval("C.red + C.transmit", "#declare C = rgbft <0.25, 0, 0, 0, 0.5>;"), 0.75);
    c = eval_color("srgb <0.5, 0.5, 0.5>");
    EXPECT_NEAR(c.rgb.r, 0.214041, 1e-6);
}

TEST(PovExpression, Strings) {
    auto s = parse(
        "#declare S = concat(\"ab\", str(1.5, 0, 2), chr(67), substr(\"xyz\", 2, 1));\n"
        "#if (strcmp(S, \"ab1.50Cy\") = 0) sphere { 0, 1 } #end");
    EXPECT_EQ(s.objects.size(), 1u);
}

TEST(PovExpression, ImageSizeClockVersion) {
    ParseOptions o;
    o.image_width = 640;
    o.image_height = 480;
    o.clock = 0.25;
    auto s = testing::parse("sphere { 0, image_width/image_height + clock }", o);
    EXPECT_DOUBLE_EQ(std::get<scene::Sphere>(s.objects[0].shape).radius, 640.0 / 480 + 0.25);
}

TEST(PovExpression, Errors) {
    EXPECT_EQ(error_of("sphere { 0, Foo }"), "1:13: unknown identifier 'Foo'");
    EXPECT_EQ(error_of("sphere { 0, \"s\" }"), "1:13: expected a float, got a string");
    EXPECT_EQ(error_of("sphere { 0, 1/0 }"), "1:14: division by zero");
    EXPECT_EQ(error_of("sphere { 0, sqrt(-1) }"), "1:13: sqrt of a negative number");
    EXPECT_EQ(error_of("sphere { 0, <1,2,3> }"),
              "1:13: expected a float, got a vector");
}

}  // namespace
}  // namespace glint::pov
