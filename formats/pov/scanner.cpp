#include "formats/pov/scanner.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace glint::pov {

namespace {

bool is_word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Scanner {
public:
    Scanner(const std::string& text, const std::shared_ptr<const std::string>& file)
        : s_(text), file_(file) {}

    std::vector<Token> run() {
        std::vector<Token> out;
        out.reserve(s_.size() / 3 + 16);
        for (;;) {
            skip_space_and_comments();
            Token t;
            t.line = line_;
            t.column = col();
            if (i_ >= s_.size()) {
                t.kind = TokKind::End;
                out.push_back(std::move(t));
                return out;
            }
            char c = s_[i_];
            if (is_word_start(c)) {
                size_t b = i_;
                while (i_ < s_.size() && is_word_char(s_[i_])) ++i_;
                t.kind = TokKind::Word;
                t.text.assign(s_, b, i_ - b);
            } else if (is_digit(c) || (c == '.' && i_ + 1 < s_.size() && is_digit(s_[i_ + 1]))) {
                scan_number(t);
            } else if (c == '"') {
                scan_string(t);
            } else if (c == '#') {
                ++i_;
                while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
                // A '#' alone at the end of a line means nothing (POV-Ray's image_size.pov
                // has one); skip it.
                if (i_ >= s_.size() || s_[i_] == '\n') continue;
                size_t b = i_;
                if (i_ < s_.size() && is_word_start(s_[i_]))
                    while (i_ < s_.size() && is_word_char(s_[i_])) ++i_;
                if (b == i_) fail(t.line, t.column, "expected a directive name after '#'");
                t.kind = TokKind::Directive;
                t.text.assign(s_, b, i_ - b);
            } else {
                scan_symbol(t);
            }
            out.push_back(std::move(t));
        }
    }

private:
    int col() const { return static_cast<int>(i_ - line_start_) + 1; }

    [[noreturn]] void fail(int line, int column, const std::string& msg) const {
        throw Error(ErrorKind::Scene, FileLoc{file_, line, column}, msg);
    }

    void newline() {
        ++line_;
        line_start_ = i_ + 1;
    }

    void skip_space_and_comments() {
        while (i_ < s_.size()) {
            char c = s_[i_];
            if (c == '\n') {
                newline();
                ++i_;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++i_;
            } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
                while (i_ < s_.size() && s_[i_] != '\n') ++i_;
            } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
                skip_block_comment();
            } else if (static_cast<unsigned char>(c) == 0xEF && i_ + 2 < s_.size() &&
                       static_cast<unsigned char>(s_[i_ + 1]) == 0xBB &&
                       static_cast<unsigned char>(s_[i_ + 2]) == 0xBF) {
                i_ += 3;  // UTF-8 byte order mark
            } else {
                return;
            }
        }
    }

    // POV-Ray block comments nest: /* a /* b */ c */ is one comment.
    void skip_block_comment() {
        int start_line = line_, start_col = col();
        int depth = 0;
        while (i_ < s_.size()) {
            if (s_[i_] == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
                ++depth;
                i_ += 2;
            } else if (s_[i_] == '*' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
                --depth;
                i_ += 2;
                if (depth == 0) return;
            } else {
                if (s_[i_] == '\n') newline();
                ++i_;
            }
        }
        fail(start_line, start_col, "unterminated comment (opened here)");
    }

    void scan_number(Token& t) {
        size_t b = i_;
        while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
        }
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            size_t j = i_ + 1;
            if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
            if (j < s_.size() && is_digit(s_[j])) {
                i_ = j;
                while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
            }
        }
        t.kind = TokKind::Number;
        t.text.assign(s_, b, i_ - b);
        t.number = std::strtod(t.text.c_str(), nullptr);
        // strtod turns a too-large literal into infinity; letting that through would poison
        // every value computed from it (and the image), so the literal itself is the error.
        if (!std::isfinite(t.number))
            fail(t.line, t.column, "number '" + t.text + "' is out of range");
    }

    void scan_string(Token& t) {
        ++i_;
        t.kind = TokKind::String;
        while (true) {
            if (i_ >= s_.size()) fail(t.line, t.column, "unterminated string (opened here)");
            // POV-Ray strings may span lines (shapes3.inc has one).
            if (s_[i_] == '\n') newline();
            char c = s_[i_++];
            if (c == '"') return;
            if (c == '\\' && i_ < s_.size()) {
                char e = s_[i_++];
                switch (e) {
                    case 'n': t.text += '\n'; break;
                    case 't': t.text += '\t'; break;
                    case 'r': t.text += '\r'; break;
                    case 'a': t.text += '\a'; break;
                    case 'b': t.text += '\b'; break;
                    case 'f': t.text += '\f'; break;
                    case 'v': t.text += '\v'; break;
                    case '0': t.text += '\0'; break;
                    case '\\': t.text += '\\'; break;
                    case '"': t.text += '"'; break;
                    case '\'': t.text += '\''; break;
                    // POV-Ray keeps unknown escapes (Windows paths) as written.
                    default: t.text += '\\'; t.text += e; break;
                }
            } else {
                t.text += c;
            }
        }
    }

    void scan_symbol(Token& t) {
        char c = s_[i_];
        char n = i_ + 1 < s_.size() ? s_[i_ + 1] : '\0';
        t.kind = TokKind::Symbol;
        if ((c == '<' || c == '>' || c == '!') && n == '=') {
            t.text = std::string{c, '='};
            i_ += 2;
            return;
        }
        static const std::string kSingles = "{}()[]<>,;=+-*/.?:!&|";
        if (kSingles.find(c) == std::string::npos) {
            std::string shown = std::isprint(static_cast<unsigned char>(c))
                                    ? std::string("'") + c + "'"
                                    : "byte " + std::to_string(static_cast<unsigned char>(c));
            fail(t.line, t.column, "unexpected character " + shown);
        }
        t.text = std::string(1, c);
        ++i_;
    }

    const std::string& s_;
    std::shared_ptr<const std::string> file_;
    size_t i_ = 0;
    size_t line_start_ = 0;
    int line_ = 1;
};

}  // namespace

std::vector<Token> scan(const std::string& text, const std::shared_ptr<const std::string>& file) {
    return Scanner(text, file).run();
}

std::string describe(const Token& t) {
    switch (t.kind) {
        case TokKind::Word: return "'" + t.text + "'";
        case TokKind::Number: return "the number " + t.text;
        case TokKind::String: return "the string \"" + t.text + "\"";
        case TokKind::Symbol: return "'" + t.text + "'";
        case TokKind::Directive: return "'#" + t.text + "'";
        case TokKind::End: return "the end of the file";
    }
    return "?";
}

}  // namespace glint::pov
