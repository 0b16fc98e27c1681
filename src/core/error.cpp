#include "core/error.h"

#include <fstream>
#include <sstream>

namespace glint {

std::string FileLoc::to_string() const {
    std::ostringstream s;
    if (file) s << *file;
    if (line > 0) {
        s << ':' << line;
        if (column > 0) s << ':' << column;
    }
    return s.str();
}

namespace {

bool read_line(const std::string& path, int line, std::string* out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::string text;
    int i = 1;
    for (; std::getline(in, text); ++i) {
        if (i == line) {
            if (!text.empty() && text.back() == '\r') text.pop_back();
            *out = text;
            return true;
        }
    }
    // A location at the end of a file that ends with a newline (an unclosed brace, say) is on
    // the empty line after the last one: show it as empty so the caret still appears.
    if (line == i) {
        out->clear();
        return true;
    }
    return false;
}

// The length of the valid UTF-8 sequence at text[i] (2 to 4 bytes), 0 when there is none.
size_t utf8_length(const std::string& text, size_t i) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = byte(i);
    size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c < 0xE0 ? 2 : 0;
    if (n == 0 || i + n > text.size()) return 0;
    for (size_t k = 1; k < n; ++k)
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
    if (c == 0xE0 && byte(i + 1) < 0xA0) return 0;  // overlong
    if (c == 0xED && byte(i + 1) >= 0xA0) return 0;  // surrogate
    if (c == 0xF0 && byte(i + 1) < 0x90) return 0;  // overlong
    if (c == 0xF4 && byte(i + 1) >= 0x90) return 0;  // past U+10FFFF
    return n;
}

// The source line as printed, and the caret under byte column `column` (1-based). Every
// character takes one column on the terminal: control bytes (a NUL, an escape) and bytes that
// are not UTF-8 print as U+FFFD, so that neither cuts the line short nor moves the caret;
// tabs stay tabs, in the caret line too, so it lines up as the terminal expands them.
void show_line(const std::string& text, int column, std::string* line, std::string* caret) {
    static const char kReplacement[] = "\xEF\xBF\xBD";
    for (size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        size_t n = 1;
        const bool before = static_cast<long long>(i) < static_cast<long long>(column) - 1;
        if (c == '\t' || (c >= 0x20 && c < 0x7F)) {
            line->push_back(static_cast<char>(c));
        } else if (c >= 0x80 && (n = utf8_length(text, i)) > 0) {
            line->append(text, i, n);
        } else {
            n = 1;
            line->append(kReplacement);
        }
        if (before) caret->push_back(c == '\t' ? '\t' : ' ');
        i += n;
    }
}

}  // namespace

std::string format_diagnostic(const FileLoc& loc, const std::string& severity,
                              const std::string& message) {
    std::ostringstream s;
    std::string where = loc.to_string();
    if (!where.empty()) s << where << ": ";
    s << severity << ": " << message << '\n';
    std::string text;
    if (loc.valid() && read_line(*loc.file, loc.line, &text)) {
        std::string line, caret;
        show_line(text, loc.column, &line, &caret);
        s << "  " << line << '\n';
        if (loc.column > 0) s << "  " << caret << "^\n";
    }
    return s.str();
}

std::string format_error(const Error& e) {
    std::string out = format_diagnostic(e.loc(), "error", e.what());
    if (!e.note().empty()) out += format_diagnostic(e.note_loc(), "note", e.note());
    return out;
}

}  // namespace glint
