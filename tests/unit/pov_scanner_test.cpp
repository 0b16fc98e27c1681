// The POV-Ray scanner: tokens, positions, comments, strings and their errors.
#include <gtest/gtest.h>

#include "core/error.h"
#include "formats/pov/scanner.h"

namespace glint::pov {
namespace {

std::vector<Token> toks(const std::string& s) {
    return scan(s, std::make_shared<const std::string>("t.pov"));
}

TEST(PovScanner, KindsAndPositions) {
    auto t = toks("sphere { <1, 2.5e1, .5>, 3 }\n  \"a\\\"b\" #declare X=1;");
    ASSERT_GE(t.size(), 18u);
    EXPECT_EQ(t[0].kind, TokKind::Word);
    EXPECT_EQ(t[0].text, "sphere");
    EXPECT_EQ(t[0].line, 1);
    EXPECT_EQ(t[0].column, 1);
    EXPECT_TRUE(t[1].is_symbol('{'));
    EXPECT_TRUE(t[2].is_symbol('<'));
    EXPECT_EQ(t[3].kind, TokKind::Number);
    EXPECT_DOUBLE_EQ(t[3].number, 1);
    EXPECT_DOUBLE_EQ(t[5].number, 25);
    EXPECT_DOUBLE_EQ(t[7].number, 0.5);
    EXPECT_EQ(t[7].column, 21);
    EXPECT_EQ(t[12].kind, TokKind::String);
    EXPECT_EQ(t[12].text, "a\"b");
    EXPECT_EQ(t[12].line, 2);
    EXPECT_EQ(t[12].column, 3);
    EXPECT_EQ(t[13].kind, TokKind::Directive);
    EXPECT_EQ(t[13].text, "declare");
    EXPECT_EQ(t.back().kind, TokKind::End);
}

TEST(PovScanner, TwoCharacterOperators) {
    auto t = toks("a<=b>=c!=d<e");
    EXPECT_EQ(t[1].text, "<=");
    EXPECT_EQ(t[3].text, ">=");
    EXPECT_EQ(t[5].text, "!=");
    EXPECT_EQ(t[7].text, "<");
}

TEST(PovScanner, CommentsNestAndVanish) {
    auto t = toks("a // line comment\n/* outer /* inner */ still comment */ b");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].text, "a");
    EXPECT_EQ(t[1].text, "b");
    EXPECT_EQ(t[1].line, 2);
}

TEST(PovScanner, DirectiveWithSpaceAfterHash) {
    auto t = toks("#   debug \"x\"");
    EXPECT_EQ(t[0].kind, TokKind::Directive);
    EXPECT_EQ(t[0].text, "debug");
}

TEST(PovScanner, LoneHashAtLineEndIsSkipped) {
    auto t = toks("a #\nb");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[1].text, "b");
}

TEST(PovScanner, ComponentAccessIsDotThenWord) {
    auto t = toks("V.x 1.5 .25");
    EXPECT_TRUE(t[1].is_symbol('.'));
    EXPECT_EQ(t[2].text, "x");
    EXPECT_DOUBLE_EQ(t[3].number, 1.5);
    EXPECT_DOUBLE_EQ(t[4].number, 0.25);
}

std::string scan_error(const std::string& s) {
    try {
        toks(s);
    } catch (const Error& e) {
        return e.loc().to_string() + ": " + e.what();
    }
    return "(no error)";
}

TEST(PovScanner, Errors) {
    EXPECT_EQ(scan_error("a\n  /* never closed"), "t.pov:2:3: unterminated comment (opened here)");
    EXPECT_EQ(scan_error("x \"abc\ndef"), "t.pov:1:3: unterminated string (opened here)");
    EXPECT_EQ(toks("\"a\nb\" c")[1].line, 2) << "strings may span lines";
    EXPECT_EQ(scan_error("a @ b"), "t.pov:1:3: unexpected character '@'");
    EXPECT_EQ(scan_error("# 3"), "t.pov:1:1: expected a directive name after '#'");
}

// A literal strtod turns into infinity must not reach the scene (it would end as NaN pixels).
TEST(PovScanner, OverflowingLiteralIsAnErrorAtTheLiteral) {
    EXPECT_EQ(scan_error("x = 1e400;"), "t.pov:1:5: number '1e400' is out of range");
    EXPECT_EQ(scan_error("a\n  2.5E+999"), "t.pov:2:3: number '2.5E+999' is out of range");
    EXPECT_DOUBLE_EQ(toks("1e300")[0].number, 1e300) << "large but finite is fine";
    EXPECT_DOUBLE_EQ(toks("1e-400")[0].number, 0) << "underflow to zero is not an error";
}

}  // namespace
}  // namespace glint::pov
