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

}  // namespace

std::string format_diagnostic(const FileLoc& loc, const std::string& severity,
                              const std::string& message) {
    std::ostringstream s;
    std::string where = loc.to_string();
    if (!where.empty()) s << where << ": ";
    s << severity << ": " << message << '\n';
    std::string text;
    if (loc.valid() && read_line(*loc.file, loc.line, &text)) {
        s << "  " << text << '\n';
        if (loc.column > 0) {
            s << "  ";
            // Keep tabs so the caret lines up with the source as the terminal shows it.
            for (int i = 0; i < loc.column - 1 && i < static_cast<int>(text.size()); ++i)
                s << (text[i] == '\t' ? '\t' : ' ');
            s << "^\n";
        }
    }
    return s.str();
}

std::string format_error(const Error& e) {
    std::string out = format_diagnostic(e.loc(), "error", e.what());
    if (!e.note().empty()) out += format_diagnostic(e.note_loc(), "note", e.note());
    return out;
}

}  // namespace glint
