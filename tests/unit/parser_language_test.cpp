// The POV-Ray language beyond the foundation: user-defined functions (parse-time calls, the
// function grammar, internal functions), splines, #fopen/#read/#write/#fclose,
// #declare deprecated, optional macro parameters, and the standard include files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "render/render.h"
#include "scene/function.h"
#include "tests/unit/pov_test_util.h"

namespace glint::pov {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::parse;

double radius(const scene::Scene& s, size_t i) {
    return std::get<scene::Sphere>(s.objects.at(i).shape).radius;
}

// The radius of the one sphere a snippet ends with `sphere { 0, EXPR }`.
double value_of(const std::string& decls, const std::string& expr) {
    auto s = parse(decls + "\nsphere { 0, " + expr + " }\n");
    return radius(s, s.objects.size() - 1);
}

std::vector<std::string> warnings_of(const std::string& text, ParseOptions opts = {}) {
    Diagnostics diag;
    parse_string(text, "test.pov", opts, diag);
    std::vector<std::string> out;
    for (const auto& d : diag.all())
        if (d.level == Diagnostic::Level::Warning && d.message.find("#version") == std::string::npos)
            out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " +
                          d.message);
    return out;
}

TEST(ParserFunction, ParseTimeCalls) {
    EXPECT_DOUBLE_EQ(value_of("#declare F = function(a, b) { a * b + 1 }", "F(2, 3)"), 7);
    EXPECT_DOUBLE_EQ(value_of("#declare F = function { x + y * 10 + z * 100 }", "F(1, 2, 3)"),
                     321);
    // u and v read the x and y registers.
    EXPECT_DOUBLE_EQ(value_of("#declare F = function(u, v) { u - v }", "F(5, 3)"), 2);
    EXPECT_DOUBLE_EQ(value_of("#declare F = function(x, y) { x - y }", "F(5, 3)"), 2);
    // Declared floats become constants; keyword constants work.
    EXPECT_DOUBLE_EQ(value_of("#declare K = 4; #declare F = function { K * x + pi - pi }",
                              "F(2, 0, 0)"),
                     8);
    // A function calls one declared before it.
    EXPECT_DOUBLE_EQ(value_of("#declare G = function(a) { a * a }\n"
                              "#declare F = function(a, b) { G(a) + G(b) }",
                              "F(3, 4)"),
                     25);
    // A call inside an ordinary expression.
    EXPECT_DOUBLE_EQ(value_of("#declare F = function(a) { a + 1 }", "2 * F(1) + 1"), 5);
}

TEST(ParserFunction, GrammarAndBuiltins) {
    auto f = [](const std::string& body) {
        return value_of("#declare F = function(a) { " + body + " }", "F(2) + 1000") - 1000;
    };
    EXPECT_DOUBLE_EQ(f("1 + 2 * 3 - a / 4"), 6.5);
    EXPECT_DOUBLE_EQ(f("-a * -a"), 4);
    // All comparisons share one level, below + and above &.
    EXPECT_DOUBLE_EQ(f("1 < 2 = 1"), 1);
    EXPECT_DOUBLE_EQ(f("a > 1 & a < 3"), 1);
    EXPECT_DOUBLE_EQ(f("a > 3 | a < 1"), 0);
    EXPECT_DOUBLE_EQ(f("a != 2"), 0);
    EXPECT_DOUBLE_EQ(f("select(a - 3, 10, 20)"), 10);
    EXPECT_DOUBLE_EQ(f("select(a - 2, 10, 20, 30)"), 20);
    EXPECT_DOUBLE_EQ(f("min(a, 5, -1) + max(a, 7)"), 6);
    EXPECT_DOUBLE_EQ(f("pow(a, 3) + mod(7, a) + div(7, a) + sqr(a)"), 8 + 1 + 3 + 4);
    EXPECT_DOUBLE_EQ(f("sum(i, 1, a + 2, i)"), 10);
    EXPECT_DOUBLE_EQ(f("prod(i, 1, 4, i)"), 24);
    EXPECT_NEAR(f("sin(pi / 2) + abs(-a) + atan2(0, 1) + floor(1.5) + ceil(1.5) + int(-1.5)"),
                1 + 2 + 0 + 1 + 2 - 1, 1e-12);
    EXPECT_NEAR(f("sqrt(a * 8) + exp(0) + ln(1) + log(100) + degrees(pi) + radians(180)"),
                4 + 1 + 0 + 2 + 180 + kPi, 1e-12);
}

TEST(ParserFunction, InternalFunctionsFromFunctionsInc) {
    if (testing::povray_include_dir().empty()) GTEST_SKIP() << "POV-Ray includes not installed";
    ParseOptions o;
    o.include_dirs = {testing::povray_include_dir()};
    auto s = parse(
        "#include \"functions.inc\"\n"
        "sphere { 0, f_sphere(3, 4, 0, 1) }\n"           // |p| - r
        "sphere { 0, f_torus(3, 0, 0, 2, 0.5) + 10 }\n"  // dist to ring - minor
        "sphere { 0, f_rounded_box(2, 0, 0, 0.1, 1, 1, 1) + 10 }\n"
        "#declare G = function { f_r(x, y, z) * 2 }\n"
        "sphere { 0, G(0, 3, 4) }\n",
        o);
    EXPECT_DOUBLE_EQ(radius(s, 0), 4);
    EXPECT_DOUBLE_EQ(radius(s, 1), 10.5);
    EXPECT_NEAR(radius(s, 2), 11, 1e-5);
    EXPECT_DOUBLE_EQ(radius(s, 3), 10);
    // functions.inc declares a function per internal, pattern and pigment function.
    EXPECT_GT(s.functions.size(), 90u);
}

TEST(ParserFunction, KindsAndIr) {
    auto s = parse(
        "#declare T = function { transform { translate <1, 2, 3> } }\n"
        "#declare P = function { pattern { checker } }\n"
        "#declare I = function { internal(61) }\n"
        "#declare E = function(a) { a }\n"
        "sphere { T(1, 1, 1), 1 }\n");
    ASSERT_EQ(s.functions.size(), 4u);
    EXPECT_EQ(s.functions[0].kind, scene::FunctionKind::Transform);
    EXPECT_EQ(s.functions[0].name, "T");
    EXPECT_EQ(s.functions[1].kind, scene::FunctionKind::Pattern);
    EXPECT_EQ(s.functions[2].kind, scene::FunctionKind::Internal);
    EXPECT_EQ(s.functions[2].params.size(), 4u);
    EXPECT_EQ(s.functions[3].params, std::vector<std::string>{"a"});
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[0].shape).center, Vec3(2, 3, 4));
}

TEST(ParserFunction, NoiseAndVturbulence) {
    // f_noise3d is POV-Ray's Noise (generator 2): in [0, 1] and not constant.
    double a = value_of("#declare N = function { internal(76) }", "N(0.3, 0.4, 0.5) + 10") - 10;
    double b = value_of("#declare N = function { internal(76) }", "N(1.3, 0.7, 2.5) + 10") - 10;
    EXPECT_GE(a, 0);
    EXPECT_LE(a, 1);
    EXPECT_NE(a, b);
    auto s = parse("sphere { vturbulence(2, 0.5, 6, <0.3, 0.4, 0.5>), 1 }\n");
    Vec3 c = std::get<scene::Sphere>(s.objects[0].shape).center;
    EXPECT_NE(c, Vec3(0, 0, 0));
    EXPECT_LT(length(c), 3);
}

TEST(ParserFunction, FunctionPatternInPigment) {
    auto s = parse(
        "#declare F = function { x * 0.5 }\n"
        "sphere { 0, 1 pigment { function { F(x, y, z) + 0.25 } color_map { [0 rgb 0] [1 rgb 1] } } }\n");
    const auto& pig = s.materials.at(static_cast<size_t>(s.objects[0].material)).texture.pigment;
    EXPECT_EQ(pig.kind, scene::PatternKind::Function);
    ASSERT_EQ(pig.params.function, 1);
    scene::FunctionEnv env;
    env.functions = &s.functions;
    double p[3] = {1, 0, 0};
    EXPECT_DOUBLE_EQ(scene::evaluate_function(env, 1, p, 3), 0.75);
}

TEST(ParserFunction, Errors) {
    EXPECT_EQ(error_of("#declare F = function { x + Nope }"),
              "1:29: unknown identifier 'Nope' in the function (a function must be declared "
              "before it is called; the f_ functions need #include \"functions.inc\")");
    EXPECT_EQ(error_of("#declare F = function { !x }"),
              "1:25: '!' cannot be used in a function (POV-Ray functions have no logical not; "
              "write 1 - (a) or select)");
    EXPECT_EQ(error_of("#declare F = function(a) { a }\n#declare V = F(1, 2);"),
              "2:14: the function 'F' takes 1 argument(s), got 2");
    EXPECT_EQ(error_of("#declare F = function(a) { a }\n#declare G = function { F(x, y) }"),
              "2:25: the function 'F' takes 1 argument(s), got 2");
    EXPECT_EQ(error_of("#declare F = function { internal(99) }"),
              "1:33: there is no internal function 99 (0 to 78)");
    EXPECT_EQ(error_of("#declare F = function { x + internal(1) }"),
              "1:29: internal(N) must be the whole function body: function { internal(N) }");
    EXPECT_EQ(error_of("#declare F = function(a) { pattern { checker } }"),
              "1:28: function parameters are not allowed for pattern functions");
    EXPECT_EQ(error_of("#declare V = <1, 2, 3>;\n#declare F = function { V }"),
              "2:25: expected a float in the function, got a vector 'V' (use V.x etc.)");
    EXPECT_EQ(error_of("#declare T = function { transform { scale 2 } }\n"
                       "#declare F = function { T(x, y, z) }"),
              "2:36: expected '.' after the call of the vector function 'T' (a function needs "
              "one component: .x, .red, .gray, ...), got '}'");
    EXPECT_EQ(error_of("#declare F = function { sin(x, y) }"),
              "1:25: 'sin' takes 1 argument, got 2");
}

TEST(ParserObjectQueries, TraceAndExtents) {
    ParseOptions o;
    o.prepare_object = render::prepare_object_query;
    auto s = parse(
        "#declare S = sphere { <1, 0, 0>, 2 }\n"
        "#declare B = box { <-1, -2, -3>, <1, 2, 3> translate x }\n"
        "#declare N = <9, 9, 9>;\n"
        "#declare P = trace(S, <1, 10, 0>, -y, N);\n"
        "sphere { P, N.y }\n"
        "sphere { min_extent(B), 1 } sphere { max_extent(B), 1 }\n"
        "#declare Q = trace(S, <10, 10, 10>, y, M);\n"
        "sphere { Q, 1 + vlength(M) }\n",
        o);
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[0].shape).center, Vec3(1, 2, 0));
    EXPECT_DOUBLE_EQ(radius(s, 0), 1);
    // The renderer's boxes are conservative by a few ulps.
    auto near = [](Vec3 a, Vec3 b) { return length(a - b) < 1e-9; };
    EXPECT_TRUE(near(std::get<scene::Sphere>(s.objects[1].shape).center, Vec3(0, -2, -3)));
    EXPECT_TRUE(near(std::get<scene::Sphere>(s.objects[2].shape).center, Vec3(2, 2, 3)));
    // A miss gives <0,0,0> and a zero normal.
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[3].shape).center, Vec3(0, 0, 0));
    EXPECT_DOUBLE_EQ(radius(s, 3), 1);
    EXPECT_EQ(error_of("#declare V = min_extent(<1, 2, 3>);", o),
              "1:25: expected an object identifier in min_extent(), got '<'");
    // Without the application's geometry the functions are not supported.
    EXPECT_EQ(error_of("#declare S = sphere { 0, 1 }\n#declare V = min_extent(S);"),
              "2:14: the 'min_extent' function is not supported yet");
}

TEST(ParserSpline, TypesAndCalls) {
    const std::string decl =
        "#declare L = spline { linear_spline 0, <0, 0, 0> 1, <2, 4, 6> 2, <2, 0, 0> }\n";
    EXPECT_DOUBLE_EQ(value_of(decl, "L(0.5).y"), 2);
    EXPECT_DOUBLE_EQ(value_of(decl, "L(1.5).x"), 2);
    EXPECT_DOUBLE_EQ(value_of(decl, "L(-1).y + 10"), 10);  // before the first: the first
    EXPECT_DOUBLE_EQ(value_of(decl, "L(5).x"), 2);         // after the last: the last
    // Entries are sorted by t; a repeated t replaces.
    EXPECT_DOUBLE_EQ(value_of("#declare S = spline { 1, <1, 1> 0, <0, 0> 1, <3, 3> }", "S(0.5).x"),
                     1.5);
    // Quadratic through (0,0) (1,1) (2,4): t^2.
    EXPECT_DOUBLE_EQ(value_of("#declare Q = spline { quadratic_spline 0, <0,0> 1, <1,1> 2, <4,4> }",
                              "Q(1.5).x"),
                     2.25);
    // Cubic (Catmull-Rom) through a straight line stays on it.
    EXPECT_NEAR(value_of("#declare C = spline { cubic_spline -1, <-1,0> 0, <0,0> 1, <1,0> "
                         "2, <2,0> 3, <3,0> }",
                         "C(0.25).x + 10"),
                10.25, 1e-12);
    // Natural cubic through a straight line too.
    EXPECT_NEAR(value_of("#declare N = spline { natural_spline 0, <0,0> 1, <1,0> 2, <2,0> "
                         "3, <3,0> }",
                         "N(1.5).x"),
                1.5, 1e-12);
    // The type can be overridden at the call.
    EXPECT_DOUBLE_EQ(value_of("#declare Q = spline { quadratic_spline 0, <0,0> 1, <1,1> 2, <4,4> }",
                              "Q(1.5, linear_spline).x"),
                     2.5);
    // A spline in a vector position, as a function, and copied with changes.
    auto s = parse(
        "#declare S = spline { 0, <1, 2, 3> 1, <3, 4, 5> }\n"
        "#declare F = function { spline { S } }\n"
        "#declare S2 = spline { S 2, <5, 6, 7> }\n"
        "sphere { S(0.5), F(0.5).z }\n"
        "sphere { S2(1.5), 1 }\n");
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[0].shape).center, Vec3(2, 3, 4));
    EXPECT_DOUBLE_EQ(radius(s, 0), 4);
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[1].shape).center, Vec3(4, 5, 6));
}

TEST(ParserSpline, Errors) {
    EXPECT_EQ(error_of("#declare S = spline { linear_spline }"),
              "1:37: a spline needs at least one entry (t, <vector>)");
    EXPECT_EQ(error_of("#declare S = spline { 0, <1,1> }\n#declare V = S(0, bezier_spline);"),
              "2:19: expected linear_spline, quadratic_spline, cubic_spline or natural_spline, "
              "got 'bezier_spline'");
}

class ParserFileIo : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("glint_fileio_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    scene::Scene parse_in_dir(const std::string& text) {
        std::ofstream(dir_ / "scene.pov") << text;
        Diagnostics diag;
        return parse_file((dir_ / "scene.pov").string(), {}, diag);
    }
    fs::path dir_;
};

TEST_F(ParserFileIo, ReadsDataFileBesideTheScene) {
    std::ofstream(dir_ / "data.txt") << "1.5, -2, <1, 2, 3>, \"text\",\n3\n";
    auto s = parse_in_dir(
        "#fopen F \"data.txt\" read\n"
        "#read (F, A, B, V, S)\n"
        "sphere { V, A - B }\n"
        "#declare N = 0;\n"
        "#while (defined(F)) #read (F, X) #declare N = N + 1; #end\n"
        "sphere { 0, N + X * 10 + strlen(S) }\n");
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[0].shape).center, Vec3(1, 2, 3));
    EXPECT_DOUBLE_EQ(radius(s, 0), 3.5);
    EXPECT_DOUBLE_EQ(radius(s, 1), 1 + 30 + 4);  // the last value closes the file
}

TEST_F(ParserFileIo, WrittenFilesAreReadBackFromMemory) {
    auto s = parse_in_dir(
        "#fopen W \"cache.inc\" write\n"
        "#write (W, 2.5, \",\", <1, 2, 3>, \",\\n\")\n"
        "#fclose W\n"
        "#fopen W \"cache.inc\" append\n"
        "#write (W, \"\\\"s\\\"\")\n"
        "#fclose W\n"
        "#fopen R \"cache.inc\" read\n"
        "#read (R, A, V, S)\n"
        "sphere { V, A + strlen(S) }\n");
    EXPECT_DOUBLE_EQ(radius(s, 0), 3.5);
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[0].shape).center, Vec3(1, 2, 3));
    EXPECT_FALSE(fs::exists(dir_ / "cache.inc"));
}

TEST(ParserFileIoErrors, Misuse) {
    EXPECT_EQ(error_of("#fopen F \"no_such_file.txt\" read"),
              "1:10: cannot find the file 'no_such_file.txt'");
    EXPECT_EQ(error_of("#fopen F \"out.txt\" readwrite"),
              "1:20: expected read, write or append after the file name in #fopen, got "
              "'readwrite'");
    EXPECT_EQ(error_of("#declare X = 1;\n#read (G, X)"), "2:8: 'G' is not a file opened with #fopen");
    EXPECT_EQ(error_of("#fopen F \"out.txt\" write\n#read (F, X)"),
              "2:8: cannot read from 'F': the file is open for writing");
    EXPECT_EQ(error_of("#write (F, 1)"), "1:9: 'F' is not a file opened with #fopen");
    // #fclose of a name that is not open is ignored (as POV-Ray).
    EXPECT_EQ(error_of("#fclose Nothing"), "(no error)");
}

TEST(ParserDirective, DeprecatedWarnsOnUse) {
    auto w = warnings_of(
        "#declare deprecated once \"use B\" A = 1;\n"
        "#declare deprecated C = 2;\n"
        "sphere { 0, A } sphere { 0, A } sphere { 0, C }\n");
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[0], "3:13: use B");
    EXPECT_EQ(w[1], "3:45: Identifier 'C' was declared deprecated.");
}

TEST(ParserDirective, OptionalMacroParameters) {
    auto s = parse(
        "#macro M(A, optional B)\n"
        "  #ifdef (B) sphere { 0, A + B } #else sphere { 0, A } #end\n"
        "#end\n"
        "M(1, 2) M(3) M(4, )\n");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(radius(s, 0), 3);
    EXPECT_DOUBLE_EQ(radius(s, 1), 3);
    EXPECT_DOUBLE_EQ(radius(s, 2), 4);
    EXPECT_EQ(error_of("#macro M(A, B) #end\nM(1)"),
              "2:4: macro 'M' expects 2 argument(s), but only 1 were given");
}

TEST(ParserDirective, DeclareModifiesAnExistingLocal) {
    // #declare of a name that exists modifies it where it is (shapes.inc's HF macros count a
    // #local up with #declare); a new name is global.
    auto s = parse(
        "#macro M() #local K = 0; #while (K < 3) #declare K = K + 1; #end #declare G = K; #end\n"
        "M() sphere { 0, G }\n"
        "#ifdef (K) sphere { 0, 100 } #end\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_DOUBLE_EQ(radius(s, 0), 3);
}

TEST(ParserDirective, LocalShadowsInsideMacros) {
    auto s = parse(
        "#declare R = 1;\n"
        "#macro M() #local R = 5; sphere { 0, R } #end\n"
        "M() sphere { 0, R }\n");
    EXPECT_DOUBLE_EQ(radius(s, 0), 5);
    EXPECT_DOUBLE_EQ(radius(s, 1), 1);
    EXPECT_EQ(error_of("#macro M() M() #end\nM()", [] {
                  ParseOptions o;
                  o.max_macro_depth = 10;
                  return o;
              }()),
              "1:12: macro calls nested deeper than 10: runaway recursion? (limit: --max-recursion)");
}

TEST(ParserDirective, DeclaredSkySphere) {
    auto s = parse(
        "#declare Sky = sky_sphere { pigment { rgb <0, 0, 1> } }\n"
        "sky_sphere { Sky pigment { rgbt <1, 1, 1, 0.5> } translate y }\n");
    ASSERT_TRUE(s.sky_sphere.has_value());
    EXPECT_EQ(s.sky_sphere->pigments.size(), 2u);
    EXPECT_EQ(s.sky_sphere->transform.point(Vec3(0, 0, 0)), Vec3(0, 1, 0));
    auto s2 = parse(
        "#declare Sky = sky_sphere { pigment { rgb <0, 0, 1> } }\n"
        "#declare Sky2 = sky_sphere { Sky scale 2 }\n"
        "sky_sphere { Sky2 }\n");
    ASSERT_TRUE(s2.sky_sphere.has_value());
    EXPECT_EQ(s2.sky_sphere->transform.point(Vec3(1, 0, 0)), Vec3(2, 0, 0));
    // Commas between macro arguments and before a vector's '>' are optional (Parse_Comma).
    auto s3 = parse("#macro M(A, B) sphere { A, B } #end\nM(<1, 2, 3,> 4)\n");
    EXPECT_DOUBLE_EQ(radius(s3, 0), 4);
    EXPECT_EQ(std::get<scene::Sphere>(s3.objects[0].shape).center, Vec3(1, 2, 3));
    // Declaring does not set the scene's sky.
    EXPECT_FALSE(parse("#declare Sky = sky_sphere { pigment { rgb 1 } }").sky_sphere.has_value());
}

TEST(ParserStandardIncludes, EveryIncludeFileParses) {
    std::string dir = testing::povray_include_dir();
    if (dir.empty()) GTEST_SKIP() << "POV-Ray includes not installed";
    ParseOptions o;
    o.include_dirs = {dir};
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().extension() != ".inc") continue;
        ++n;
        std::string name = e.path().filename().string();
        SCOPED_TRACE(name);
        try {
            Diagnostics diag;
            // Several includes use colors.inc's and shapes.inc's names without including them.
            parse_string("#version 3.7;\n#include \"colors.inc\"\n#include \"shapes.inc\"\n#include \"" + name + "\"\n",
                         "test.pov", o, diag);
        } catch (const Error& err) {
            ADD_FAILURE() << name << ": " << err.what() << " at " << err.loc().filename() << ":"
                          << err.loc().line;
        }
    }
    EXPECT_GE(n, 39);
}

TEST(PovLanguage, StringsCompareLikeStrcmp) {
    EXPECT_EQ(value_of("#declare S = \"abc\";", "(S = \"abc\") + 1"), 2);
    EXPECT_EQ(value_of("#declare S = \"\";", "(S != \"\") + 1"), 1);
    EXPECT_EQ(value_of("", "(\"a\" < \"b\") + (\"b\" <= \"a\") + 1"), 2);
    EXPECT_EQ(error_of("#if (\"a\" = 1) #end"), "1:13: expected a string to compare with a string");
}

TEST(PovLanguage, CountsBeforePointListsAndTrailingCommas) {
    // mesh2 as POV-Ray's own objects/mesh2.pov writes it: no comma after the count, one
    // after the last vector.
    auto s = parse(
        "mesh2 { vertex_vectors { 3 <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, }\n"
        "  face_indices { 1 <0, 1, 2> } }\n");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].positions.size(), 3u);
    EXPECT_EQ(s.meshes[0].faces.size(), 1u);
}

TEST(PovLanguage, UvMappingInAPlainTextureMapsItsPigment) {
    auto s = parse("sphere { 0, 1 texture { uv_mapping pigment { checker } } }");
    EXPECT_TRUE(s.materials.back().texture.pigment.uv_mapping);
}

TEST(PovLanguage, ArrayInitializerCommasAreOptional) {
    // As in POV-Ray's grenadine/lemon.inc: rows of vectors without a comma between them.
    EXPECT_EQ(value_of("#declare A = array[4] { <1, 2>, <3, 4> <5, 6>, <7, 8> }", "A[2].u"), 5);
    EXPECT_EQ(value_of("#declare B = array[2][2] { {1, 2} {3, 4} }", "B[1][0]"), 3);
}

TEST(PovLanguage, LocalTakesAMacroCallsValueIntoTheCallersScope) {
    // transforms.inc's Spline_Trans: `#local Matrix = Matrix_Trans(...)` without a semicolon;
    // the called macro's scope is still open when the value ends, the #local must not land
    // there.
    EXPECT_EQ(value_of("#macro Two() 2 #end\n"
                       "#macro Outer() #local V = Two() #local W = V + 1; W #end",
                       "Outer()"),
              3);
}

TEST(PovLanguage, InsideAndEvalPigment) {
    ParseOptions o;
    o.prepare_object = render::prepare_object_query;
    o.pattern_hook = render::parse_time_pattern;
    auto s = parse(
        "#declare S = difference { sphere { 0, 1 } sphere { 0, 0.5 } translate x }\n"
        "#declare P = pigment { gradient x color_map { [0 rgb <0, 0, 1>] [1 rgb <1, 0, 0>] } }\n"
        "#declare C = eval_pigment(P, <0.25, 7, 7>);\n"
        "sphere { <inside(S, <0.2, 0, 0>), inside(S, <1, 0, 0>), inside(S, <1.7, 0, 0>)>, "
        "1 + C.red + 10 * C.blue }\n",
        o);
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[0].shape).center, Vec3(1, 0, 1));
    EXPECT_DOUBLE_EQ(radius(s, 0), 1 + 0.25 + 7.5);
    // With no renderer to ask, inside() warns and gives 0.
    EXPECT_EQ(warnings_of("#declare S = sphere { 0, 1 }\n#declare A = inside(S, <0, 0, 0>);\n"
                          "sphere { 0, A + 1 }"),
              (std::vector<std::string>{"2:14: 'inside()' is not supported: it gives 0"}));
}

TEST(PovLanguage, NowAndDatetime) {
    auto s = parse("#declare D = datetime(0.5, \"%Y/%m/%d %H\");\n"
                   "sphere { 0, strlen(D) + (now > 9000) + (strcmp(D, \"2000/01/01 12\") = 0) }");
    EXPECT_DOUBLE_EQ(radius(s, 0), 13 + 1 + 1);
}

}  // namespace
}  // namespace glint::pov
