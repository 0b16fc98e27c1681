// The POV-Ray directive layer: #declare/#local, #if family, loops, macros, #switch,
// #include with its search path, limits, and the tolerant handling of standard includes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/unit/pov_test_util.h"

namespace glint::pov {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::parse;

double radius(const scene::Scene& s, size_t i) {
    return std::get<scene::Sphere>(s.objects.at(i).shape).radius;
}

TEST(PovDirective, WhileForAndConditionals) {
    auto s = parse(
        "#declare I = 0;\n"
        "#while (I < 3) sphere { 0, I + 1 } #declare I = I + 1; #end\n"
        "#for (J, 10, 12, 2) sphere { 0, J } #end\n"
        "#if (I = 3) sphere { 0, 100 } #elseif (1) sphere { 0, 200 } #else sphere { 0, 300 } #end\n"
        "#if (0) sphere { 0, 1000 } #elseif (1) sphere { 0, 400 } #end\n"
        "#ifdef (I) sphere { 0, 500 } #end #ifndef (Nope) sphere { 0, 600 } #end\n"
        "#ifdef (Nope) sphere { 0, 9 } #else sphere { 0, 700 } #end\n");
    std::vector<double> r;
    for (size_t i = 0; i < s.objects.size(); ++i) r.push_back(radius(s, i));
    EXPECT_EQ(r, (std::vector<double>{1, 2, 3, 10, 12, 100, 400, 500, 600, 700}));
}

TEST(PovDirective, NestedLoopsAndDeclaresWithoutSemicolon) {
    auto s = parse(
        "#declare A = union { sphere { 0, 1 } }\n"
        "#declare B = object { A }\n"
        "#declare N = 0;\n"
        "#while (N < 2) #declare M = 0; #while (M < 2) object { B } #declare M = M + 1; #end\n"
        "#declare N = N + 1; #end\n");
    EXPECT_EQ(s.objects.size(), 4u);
}

TEST(PovDirective, SwitchCaseRangeBreak) {
    auto pick = [](double v) {
        auto s = parse("#switch (" + std::to_string(v) +
                       ")\n #case (1) sphere { 0, 10 } #break\n"
                       " #range (2, 4) sphere { 0, 20 } #break\n"
                       " #case (5) sphere { 0, 30 }\n"  // falls through to #else
                       " #else sphere { 0, 40 }\n#end");
        std::vector<double> r;
        for (size_t i = 0; i < s.objects.size(); ++i) r.push_back(radius(s, i));
        return r;
    };
    EXPECT_EQ(pick(1), (std::vector<double>{10}));
    EXPECT_EQ(pick(3), (std::vector<double>{20}));
    EXPECT_EQ(pick(5), (std::vector<double>{30, 40}));
    EXPECT_EQ(pick(9), (std::vector<double>{40}));
}

TEST(PovDirective, MacrosReturnValuesAndObjectsWithLocalScope) {
    auto s = parse(
        "#macro Twice(V) #local T = V * 2; T #end\n"
        "#macro Ball(R) sphere { 0, R } #end\n"
        "#macro Pick(A) #if (A > 0) 1 #else 2 #end #end\n"
        "#declare X = Twice(3);\n"
        "sphere { 0, X }\n"
        "Ball(Twice(2))\n"
        "sphere { 0, Pick(5) + Pick(-1) * 10 }\n"
        "#ifdef (T) sphere { 0, 999 } #end\n");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(radius(s, 0), 6);
    EXPECT_EQ(radius(s, 1), 4);
    EXPECT_EQ(radius(s, 2), 21);
}

TEST(PovDirective, MacroIdentifierArgumentsAreByReference) {
    auto s = parse(
        "#macro Inc(V) #declare V = V + 1; #end\n"
        "#declare Count = 1;\nInc(Count)\nInc(Count)\n"
        "#macro Scoped() #local L = 5; Inc(L) sphere { 0, L } #end\nScoped()\n"
        "sphere { 0, Count }\n#ifdef (V) sphere { 0, 99 } #end\n");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(radius(s, 0), 6);
    EXPECT_EQ(radius(s, 1), 3);
}

TEST(PovDirective, LocalOnAByReferenceParameterWritesThrough) {
    // POV-Ray assigns through a parameter passed by reference with #local too, down a chain
    // of macros passing it on (measured with POV-Ray 3.7; tracevines.pov's Grow relies on it
    // to move its caller's root, and its vines never stopped growing without it).
    auto s = parse(
        "#macro Set(P) #local P = 7; #end\n"
        "#macro Pass(Q) Set(Q) #end\n"
        "#macro Outer() #local Root = 1; Pass(Root) sphere { 0, Root } #end\n"
        "Outer()\n"
        "#macro Own(P) #local Fresh = P + 1; sphere { 0, Fresh } #end\n"
        "#declare G = 2;\nOwn(G)\nsphere { 0, G }\n");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(radius(s, 0), 7);
    EXPECT_EQ(radius(s, 1), 3);
    EXPECT_EQ(radius(s, 2), 2);  // a new local name leaves the argument alone
}

TEST(PovDirective, StringDeclareNeedsNoSemicolon) {
    auto s = parse("#macro Len(S) sphere { 0, strlen(S) } #end\n"
                   "#declare Name = \"abcd\"\nLen(Name)\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(radius(s, 0), 4);
}

TEST(PovDirective, DeclaredValueMayStartWithADirective) {
    auto s = parse("#declare S =\n#ifdef (Nope) sphere { 0, 1 } #else sphere { 0, 2 } #end\n"
                   "object { S }\n#declare N = #if (1) 3 #else 4 #end;\nsphere { 0, N }");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(radius(s, 0), 2);
    EXPECT_EQ(radius(s, 1), 3);
}

TEST(PovDirective, UndefVersionDebugDefault) {
    Diagnostics diag;
    auto s = parse_string(
        "#version 3.6;\n#declare A = 1;\n#undef A\n#ifndef (A) sphere { 0, 1 } #end\n"
        "#warning \"careful\"\n#default { finish { ambient 0.3 } }\nsphere { 0, 2 }",
        "t.pov", {}, diag);
    EXPECT_DOUBLE_EQ(s.version, 3.6);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.materials[s.objects[1].material].texture.finish.ambient, Color(0.3, 0.3, 0.3));
    EXPECT_EQ(s.materials[s.objects[0].material].texture.finish.ambient, Color(0.1, 0.1, 0.1));
    ASSERT_EQ(diag.warning_count(), 1);
    EXPECT_EQ(diag.all()[0].message, "careful");
    EXPECT_EQ(diag.all()[0].loc.line, 5);
}

TEST(PovDirective, ArraysAndRandomStreams) {
    auto s = parse(
        "#declare A = array[3] { 1, 2, 3 };\n"
        "#declare B = array[2][2] { {sphere{0,1}, sphere{0,2}}, {sphere{0,3}, sphere{0,4}} }\n"
        "#declare A[1] = 20;\n#declare C = A;\n#declare C[0] = 100;\n"
        "sphere { 0, A[0] + A[1] + dimension_size(A, 1) + dimensions(B) }\n"
        "object { B[1][0] }\n"
        "#ifdef (A[2]) sphere { 0, C[0] } #end\n"
        "#declare D = array[2]\n#ifndef (D[1]) sphere { 0, 7 } #end\n"
        "#declare R = seed(42);\nsphere { 0, rand(R) }\nsphere { 0, rand(R) }\n");
    ASSERT_EQ(s.objects.size(), 6u);
    EXPECT_EQ(radius(s, 0), 1 + 20 + 3 + 2);
    EXPECT_EQ(radius(s, 1), 3);
    EXPECT_EQ(radius(s, 2), 100);  // C is a copy: A[0] stayed 1
    EXPECT_EQ(radius(s, 3), 7);
    // POV-Ray 3.7 prints 0.723583 and 0.329979 for these (its LCG, randomsequences.cpp).
    EXPECT_NEAR(radius(s, 4), 0.723583, 1e-6);
    EXPECT_NEAR(radius(s, 5), 0.329979, 1e-6);
    EXPECT_EQ(error_of("#declare A = array[2];\nsphere { 0, A[1] }"),
              "2:13: array element A[1] is not initialized");
    EXPECT_EQ(error_of("#declare A = array[2] {1, 2};\nsphere { 0, A[2] }"),
              "2:15: index 2 is outside the array 'A' (size 2)");
}

TEST(PovDirective, Errors) {
    EXPECT_EQ(error_of("sphere{0,1}\n  #error \"stop here\""), "2:3: #error: stop here");
    EXPECT_EQ(error_of("#if (1) sphere{0,1}\n"), "1:1: this directive has no matching #end before the end of the file");
    EXPECT_EQ(error_of("#end"), "1:1: #end without a matching #if, #while, #for, #switch or #macro");
    EXPECT_EQ(error_of("#frobnicate"), "1:1: unknown directive '#frobnicate'");
    EXPECT_EQ(error_of("#declare X = 1;\n#declare Y = X + Z;"), "2:18: unknown identifier 'Z'");
    ParseOptions small;
    small.max_loop_iterations = 100;
    EXPECT_EQ(error_of("#while (1) #end", small), "1:1: #while loop ran more than 100 iterations (limit: --max-loop-iterations)");
    EXPECT_EQ(error_of("#macro R(N) R(N + 1) #end\nsphere { 0, R(1) }"),
              "1:13: macro calls nested deeper than 256: runaway recursion? (limit: --max-recursion)");
}

// The body's text alone does not say which call failed: the note names the call site.
TEST(PovDirective, ErrorInMacroBodyNotesTheCallSite) {
    const std::string text =
        "#macro Ball(R)\n  sphere { 0, R * Missing }\n#end\n"
        "#macro Outer() Ball(2) #end\n"
        "sphere { 0, 1 }\n  Ball(1)\n";
    try {
        parse(text);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_EQ(e.loc().column, 19);
        EXPECT_STREQ(e.what(), "unknown identifier 'Missing'");
        EXPECT_EQ(e.note(), "in macro 'Ball' called here");
        EXPECT_EQ(e.note_loc().line, 6);
        EXPECT_EQ(e.note_loc().column, 3);
        std::string shown = format_error(e);
        EXPECT_NE(shown.find("test.pov:6:3: note: in macro 'Ball' called here"),
                  std::string::npos)
            << shown;
    }
    // Nested calls: the innermost macro's call (inside Outer's body) is the one named.
    try {
        parse(text.substr(0, text.find("sphere { 0, 1 }")) + "Outer()\n");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.note(), "in macro 'Ball' called here");
        EXPECT_EQ(e.note_loc().line, 4);
        EXPECT_EQ(e.note_loc().column, 16);
    }
    // An error outside any macro body has no note; one after a call returned neither.
    try {
        parse("#macro M() 1 #end\n#declare X = M() + Nope;\n");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "unknown identifier 'Nope'");
        EXPECT_TRUE(e.note().empty()) << e.note();
    }
}

class PovIncludeTest : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() /
               ("glint_pov_inc_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(root / "scene");
        fs::create_directories(root / "sys");
    }
    void TearDown() override { fs::remove_all(root); }
    void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
    scene::Scene parse_scene(const std::string& text) {
        write(root / "scene" / "main.pov", text);
        ParseOptions o;
        o.include_dirs.push_back((root / "sys").string());
        Diagnostics diag;
        return parse_file((root / "scene" / "main.pov").string(), o, diag);
    }
    fs::path root;
};

TEST_F(PovIncludeTest, SearchPathOrderAndScopes) {
    write(root / "sys" / "lib.inc", "#declare Size = 2;\n#local Hidden = 5;\n");
    write(root / "scene" / "local.inc", "#declare Size2 = Size * 10;\n");
    auto s = parse_scene("#include \"lib.inc\"\n#include \"local.inc\"\n"
                         "sphere { 0, Size2 }\n#ifdef (Hidden) sphere { 0, 1 } #end\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(radius(s, 0), 20);
    EXPECT_EQ(s.source_files.size(), 3u);
}

TEST_F(PovIncludeTest, MissingIncludeIsMissingFileAtTheString) {
    try {
        parse_scene("sphere { 0, 1 }\n#include   \"nope.inc\"\n");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::MissingFile);
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_EQ(e.loc().column, 12);
        EXPECT_STREQ(e.what(), "cannot find include file 'nope.inc'");
    }
}

TEST_F(PovIncludeTest, StandardIncludeSkipsUnsupportedDeclarations) {
    write(root / "sys" / "std.inc",
          "#declare Good = 1;\n#declare Bad = rainbow { angle 42 }\n"
          "#declare Also = texture { pigment { rgb 1 } }\n");
    auto s = parse_scene("#include \"std.inc\"\nsphere { 0, Good texture { Also } }\n");
    EXPECT_EQ(s.objects.size(), 1u);
    try {
        parse_scene("#include \"std.inc\"\nsphere { 0, 1 pigment { Bad } }\n");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_EQ(e.loc().column, 25);
        EXPECT_NE(std::string(e.what()).find("'Bad' cannot be used"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("declaring 'rainbow' is not supported yet"),
                  std::string::npos);
        EXPECT_EQ(e.note_loc().line, 2);
        EXPECT_NE(e.note_loc().filename().find("std.inc"), std::string::npos);
    }
}

// A note made deeper (where the skipped declaration is) is more specific than the macro's.
TEST_F(PovIncludeTest, MacroCallDoesNotReplaceAnExistingNote) {
    write(root / "sys" / "std.inc", "#declare Good = 1;\n#declare Bad = rainbow { angle 42 }\n");
    try {
        parse_scene("#include \"std.inc\"\n#macro M() sphere { 0, 1 pigment { Bad } } #end\nM()\n");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'Bad' cannot be used"), std::string::npos);
        EXPECT_NE(e.note_loc().filename().find("std.inc"), std::string::npos);
        EXPECT_EQ(e.note_loc().line, 2);
    }
}

TEST_F(PovIncludeTest, IncludeNamingAFolderSaysSo) {
    fs::create_directories(root / "scene" / "parts.inc");
    try {
        parse_scene("#include \"parts.inc\"\n");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::MissingFile);
        EXPECT_EQ(e.loc().line, 1);
        EXPECT_EQ(e.loc().column, 10);
        EXPECT_STREQ(e.what(), "'parts.inc' is a folder, not a file");
    }
    // A real file further along the search path still wins over the folder.
    write(root / "sys" / "parts.inc", "#declare Size = 3;\n");
    auto s = parse_scene("#include \"parts.inc\"\nsphere { 0, Size }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(radius(s, 0), 3);
}

TEST_F(PovIncludeTest, SceneOwnFilesAreStrict) {
    write(root / "scene" / "mine.inc", "#declare Bad = rainbow { angle 42 }\n");
    try {
        parse_scene("#include \"mine.inc\"\n");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().line, 1);
        EXPECT_EQ(e.loc().column, 16);
        EXPECT_STREQ(e.what(), "declaring 'rainbow' is not supported yet");
    }
}

TEST_F(PovIncludeTest, IncludeDepthLimit) {
    write(root / "scene" / "self.inc", "#include \"self.inc\"\n");
    write(root / "scene" / "main.pov", "#include \"self.inc\"\n");
    ParseOptions o;
    o.max_include_depth = 8;
    Diagnostics diag;
    try {
        parse_file((root / "scene" / "main.pov").string(), o, diag);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "#include nested deeper than 8 files (limit: --max-include-depth)");
    }
}

}  // namespace
}  // namespace glint::pov
