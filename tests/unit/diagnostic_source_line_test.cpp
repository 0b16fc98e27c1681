// The source line and caret under an error: control bytes, bytes that are not UTF-8 and
// multi-byte characters each take one column, and tabs stay tabs, so the caret stays under
// the culprit whatever the line holds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "core/error.h"

namespace {

// format_diagnostic for one line of text at byte column `column`: its 2nd and 3rd lines.
std::pair<std::string, std::string> shown(const std::string& text, int column) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("glint_diag_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                       std::to_string(column) + ".pov");
    {
        std::ofstream out(path, std::ios::binary);
        out << text << "\n";
    }
    glint::FileLoc loc{std::make_shared<const std::string>(path.string()), 1, column};
    const std::string d = glint::format_diagnostic(loc, "error", "x");
    std::filesystem::remove(path);
    const size_t a = d.find('\n'), b = d.find('\n', a + 1), c = d.find('\n', b + 1);
    return {d.substr(a + 1, b - a - 1), d.substr(b + 1, c - b - 1)};
}

const std::string kBox = "\xEF\xBF\xBD";  // U+FFFD

TEST(DiagnosticSourceLine, NulByteIsShownAndCaretStaysUnderTheColumn) {
    const std::string text = std::string("a /* ") + '\0' + " */ Bad";
    auto [line, caret] = shown(text, 11);  // 'B'
    EXPECT_EQ(line, "  a /* " + kBox + " */ Bad");
    EXPECT_EQ(caret, "  " + std::string(10, ' ') + "^");
}

TEST(DiagnosticSourceLine, EscapeAndDeleteAreReplaced) {
    auto [line, caret] = shown("\x1b[31m\x7f X", 8);
    EXPECT_EQ(line, "  " + kBox + "[31m" + kBox + " X");
    EXPECT_EQ(caret, "  " + std::string(7, ' ') + "^");
}

TEST(DiagnosticSourceLine, TabsStayTabsInTheCaretLine) {
    auto [line, caret] = shown("\t\tsphere { 0, R }", 15);  // 'R'
    EXPECT_EQ(line, "  \t\tsphere { 0, R }");
    EXPECT_EQ(caret, "  \t\t" + std::string(12, ' ') + "^");
}

TEST(DiagnosticSourceLine, Utf8CharacterTakesOneColumn) {
    // "é" is two bytes: the culprit after it is at byte column 7 but on screen column 6.
    auto [line, caret] = shown("// \xC3\xA9 Bad", 7);
    EXPECT_EQ(line, "  // \xC3\xA9 Bad");
    EXPECT_EQ(caret, "  " + std::string(5, ' ') + "^");
}

TEST(DiagnosticSourceLine, InvalidUtf8BytesAreReplacedOneEach) {
    auto [line, caret] = shown("\xC3(\xFF Bad", 5);
    EXPECT_EQ(line, "  " + kBox + "(" + kBox + " Bad");
    EXPECT_EQ(caret, "  " + std::string(4, ' ') + "^");
}

TEST(DiagnosticSourceLine, CaretJustPastTheEnd) {
    auto [line, caret] = shown("Ka 1 2", 7);
    EXPECT_EQ(line, "  Ka 1 2");
    EXPECT_EQ(caret, "  " + std::string(6, ' ') + "^");
}

}  // namespace
