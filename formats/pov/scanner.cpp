#include "formats/pov/scanner.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace glint::pov {

namespace {

bool is_word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// One of { } ( ) [ ] < > , ; = + - * / . ? : ! & |
bool is_single_symbol(char c) {
    switch (c) {
        case '{': case '}': case '(': case ')': case '[': case ']': case '<': case '>':
        case ',': case ';': case '=': case '+': case '-': case '*': case '/': case '.':
        case '?': case ':': case '!': case '&': case '|':
            return true;
        default:
            return false;
    }
}

// The mesh2 lists whose bodies may become one NumberList token.
bool is_list_keyword(const std::string& w) {
    return w == "vertex_vectors" || w == "normal_vectors" || w == "uv_vectors" ||
           w == "face_indices" || w == "normal_indices" || w == "uv_indices";
}

bool is_list_char(char c) {
    return is_digit(c) || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-' || c == ',' ||
           c == '<' || c == '>' || c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

class Scanner {
public:
    Scanner(const std::string& text, const std::shared_ptr<const std::string>& file, int line,
            int column, bool lists)
        : s_(text), file_(file), line_(line), lists_(lists) {
        // The first line starts column - 1 characters before the text does.
        line_start_ = 0;
        first_line_offset_ = column - 1;
    }

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
                if (lists_ && is_list_keyword(t.text)) {
                    out.push_back(std::move(t));
                    number_list(out);
                    continue;
                }
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
    int col() const {
        return static_cast<int>(i_ - line_start_) + 1 + (line_start_ == 0 ? first_line_offset_ : 0);
    }

    // After a list keyword: `{`, a body of list characters only, `}` becomes three tokens, the
    // body one NumberList. Anything else is left for the ordinary scan (nothing is consumed).
    void number_list(std::vector<Token>& out) {
        size_t j = i_;
        while (j < s_.size() && (s_[j] == ' ' || s_[j] == '\t' || s_[j] == '\r' || s_[j] == '\n'))
            ++j;
        if (j >= s_.size() || s_[j] != '{') return;
        const size_t body = j + 1;
        size_t k = body;
        while (k < s_.size() && is_list_char(s_[k])) ++k;
        if (k >= s_.size() || s_[k] != '}') return;
        skip_space_and_comments();  // to the '{', counting lines
        Token open;
        open.kind = TokKind::Symbol;
        open.text = "{";
        open.line = line_;
        open.column = col();
        out.push_back(std::move(open));
        ++i_;
        Token list;
        list.kind = TokKind::NumberList;
        list.line = line_;
        list.column = col();
        list.text.assign(s_, body, k - body);
        out.push_back(std::move(list));
        for (; i_ < k; ++i_)
            if (s_[i_] == '\n') newline();
        // The '}' is scanned next, as usual.
    }

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
        // from_chars rounds as strtod does (correctly), several times faster; out of its range
        // it leaves the value alone, and strtod says what that range end is (0 or a
        // subnormal below, infinity above).
        const char* first = s_.data() + b;
        const char* last = s_.data() + i_;
        const auto r = std::from_chars(first, last, t.number);
        if (r.ec != std::errc() || r.ptr != last) t.number = std::strtod(t.text.c_str(), nullptr);
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
        if (!is_single_symbol(c)) {
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
    int first_line_offset_ = 0;  // columns before the text on its first line
    bool lists_ = true;
};

}  // namespace

std::vector<Token> scan(const std::string& text, const std::shared_ptr<const std::string>& file,
                        int line, int column, bool lists) {
    return Scanner(text, file, line, column, lists).run();
}

std::string describe(const Token& t) {
    switch (t.kind) {
        case TokKind::Word: return "'" + t.text + "'";
        case TokKind::Number: return "the number " + t.text;
        case TokKind::String: return "the string \"" + t.text + "\"";
        case TokKind::Symbol: return "'" + t.text + "'";
        case TokKind::Directive: return "'#" + t.text + "'";
        case TokKind::NumberList: return "a list of numbers";
        case TokKind::End: return "the end of the file";
    }
    return "?";
}

}  // namespace glint::pov
