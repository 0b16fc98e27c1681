#include "formats/obj/obj_checks.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

namespace glint::obj {

FileLoc file_loc(const std::shared_ptr<const std::string>& file, int line, int column) {
    FileLoc l;
    l.file = file;
    l.line = line;
    l.column = line > 0 ? column : 0;
    return l;
}

// tinyobjloader reports lines as "(line 12.)", "... line 12.)" or "line: 12", after any text it
// quotes from the file (a material name may read "line4444..."): the last such number, 0 when
// there is none or it does not fit an int.
int reported_line(const std::string& message) {
    int found = 0;
    for (size_t at = message.find("line"); at != std::string::npos;
         at = message.find("line", at + 1)) {
        size_t i = at + 4;
        if (i < message.size() && message[i] == ':') ++i;
        while (i < message.size() && message[i] == ' ') ++i;
        const size_t digits = i;
        long long value = 0;
        for (; i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])); ++i)
            value = std::min(value * 10 + (message[i] - '0'), 1LL << 40);
        if (i == digits) continue;
        found = value <= std::numeric_limits<int>::max() ? static_cast<int>(value) : 0;
    }
    return found;
}

std::string first_line(const std::string& s) {
    std::string t = s.substr(0, s.find('\n'));
    while (!t.empty() && (t.back() == '\r' || t.back() == ' ')) t.pop_back();
    return t;
}

// The line of the k-th (0-based) `cmd` statement (v, vt, vn) of the file, 0 when not found.
int statement_line(const std::string& path, const char* cmd, size_t k) {
    std::ifstream in(path);
    std::string line;
    size_t seen = 0;
    for (int line_no = 1; std::getline(in, line); ++line_no) {
        std::istringstream ls(line);
        std::string c;
        if (ls >> c && c == cmd && seen++ == k) return line_no;
    }
    return 0;
}

namespace {

// One whitespace-separated field of a statement and its 1-based column.
struct Field {
    std::string_view text;
    int column = 0;
};

// The fields of one line (spaces, tabs and a CR separate them; a `#` starts a comment), at
// most `max` of them; returns how many there are in all. Allocation-free: it runs on every
// line of an OBJ file.
template <size_t N>
size_t split_fields(std::string_view line, Field (&out)[N]) {
    size_t n = 0, i = 0;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
    while (i < line.size()) {
        while (i < line.size() && space(line[i])) ++i;
        if (i >= line.size() || line[i] == '#') break;
        size_t b = i;
        while (i < line.size() && !space(line[i]) && line[i] != '#') ++i;
        if (n < N) out[n] = Field{line.substr(b, i - b), static_cast<int>(b) + 1};
        ++n;
    }
    return n;
}

// What a value field holds: a finite number, something else, or a number out of range.
enum class NumberCheck { Ok, NotANumber, NotFinite };

NumberCheck check_number(std::string_view s) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);  // from_chars takes '-' but not '+'
    if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '.' ||
                       s[0] == '-'))
        return NumberCheck::NotANumber;  // also keeps out from_chars' "inf" and "nan"
    if (s[0] == '-' && (s.size() < 2 || !(std::isdigit(static_cast<unsigned char>(s[1])) ||
                                          s[1] == '.')))
        return NumberCheck::NotANumber;
    double x = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
    if (ec == std::errc::result_out_of_range) return NumberCheck::NotFinite;
    if (ec != std::errc() || end != s.data() + s.size()) return NumberCheck::NotANumber;
    return std::isfinite(x) ? NumberCheck::Ok : NumberCheck::NotFinite;
}

std::string shown(std::string_view s) {
    return s.size() > 40 ? std::string(s.substr(0, 40)) + "..." : std::string(s);
}

// Checks that a statement's values are numbers: at least `min_count`, and all of the first
// `check_count` fields after the keyword (tinyobjloader reads a field that is not a number,
// or a missing one, as 0 without a word). `what` names the values for the message.
template <size_t N>
void check_values(const Field (&f)[N], size_t n, size_t min_count, size_t check_count,
                  const char* what, const std::shared_ptr<const std::string>& file,
                  int line_no) {
    const std::string key(f[0].text);
    const size_t values = n - 1;
    for (size_t k = 1; k <= std::min({values, check_count, N - 1}); ++k) {
        NumberCheck c = check_number(f[k].text);
        if (c == NumberCheck::NotANumber)
            throw Error(ErrorKind::Scene, file_loc(file, line_no, f[k].column),
                        "'" + key + "' value '" + shown(f[k].text) + "' is not a number");
        if (c == NumberCheck::NotFinite)
            throw Error(ErrorKind::Scene, file_loc(file, line_no, f[k].column),
                        "'" + key + "' value '" + shown(f[k].text) +
                            "' is out of range (not a finite number)");
    }
    if (values < min_count) {
        const Field& last = f[std::min(values, N - 1)];
        int col = last.column + static_cast<int>(last.text.size());  // just past it
        throw Error(ErrorKind::Scene, file_loc(file, line_no, col),
                    "'" + key + "' needs " +
                        (min_count == 1 ? std::string("a number")
                                        : std::to_string(min_count) + " numbers (" + what + ")") +
                        ", found " + (values == 0 ? std::string("none") : std::to_string(values)));
    }
}

}  // namespace

// `vw` statements (skin weights) mean nothing to glint, which has no skinning, and
// tinyobjloader's reader of them casts joint ids to int unchecked (1e26 or inf is undefined
// behaviour, found by fuzz_obj under UBSan). Each becomes a comment before tinyobjloader reads
// the text, split into lines as tinyobjloader splits them (at \n, \r or \r\n), and the
// first is named in one warning.
void drop_skin_weights(std::string& text, const std::shared_ptr<const std::string>& file,
                       Diagnostics& diag) {
    int line_no = 1, dropped = 0, first_line = 0;
    for (size_t i = 0; i < text.size();) {
        size_t a = i;
        while (a < text.size() && (text[a] == ' ' || text[a] == '\t')) ++a;
        if (a + 2 < text.size() && text[a] == 'v' && text[a + 1] == 'w' &&
            (text[a + 2] == ' ' || text[a + 2] == '\t')) {
            text[a] = '#';
            if (dropped++ == 0) first_line = line_no;
        }
        while (i < text.size() && text[i] != '\n' && text[i] != '\r') ++i;
        if (i < text.size() && text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        if (i < text.size()) ++i;
        ++line_no;
    }
    if (dropped > 0)
        diag.warning(file_loc(file, first_line),
                     "'vw' statements (skin weights) are ignored: glint has no skinning (" +
                         std::to_string(dropped) + " in the file)");
}

void drop_undefined_normals(std::string& text, const std::shared_ptr<const std::string>& file,
                            Diagnostics& diag) {
    auto is_blank = [](char c) { return c == ' ' || c == '\t'; };
    // Each line as tinyobjloader splits them (at \n, \r or \r\n): [start, end).
    auto for_each_line = [&](auto visit) {
        int line_no = 1;
        for (size_t i = 0; i < text.size(); ++line_no) {
            size_t end = i;
            while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
            size_t a = i;
            while (a < end && is_blank(text[a])) ++a;
            if (!visit(a, end, line_no)) return;
            i = end;
            if (i < text.size() && text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n')
                ++i;
            if (i < text.size()) ++i;
        }
    };
    bool has_normals = false;
    for_each_line([&](size_t a, size_t end, int) {
        has_normals = a + 2 < end && text[a] == 'v' && text[a + 1] == 'n' && is_blank(text[a + 2]);
        return !has_normals;
    });
    if (has_normals) return;
    int faces = 0, first_line = 0;
    for_each_line([&](size_t a, size_t end, int line_no) {
        if (!(a + 1 < end && text[a] == 'f' && is_blank(text[a + 1]))) return true;
        bool dropped = false;
        for (size_t c = a + 2; c < end;) {  // each corner v[/vt[/vn]]
            while (c < end && is_blank(text[c])) ++c;
            size_t e = c;
            while (e < end && !is_blank(text[e])) ++e;
            const size_t s1 = text.find('/', c);
            const size_t s2 = s1 < e ? text.find('/', s1 + 1) : std::string::npos;
            if (s2 < e) {
                // v//vn loses both slashes, v/vt/vn its second: blanks keep the columns.
                for (size_t k = s2 == s1 + 1 ? s1 : s2; k < e; ++k) text[k] = ' ';
                dropped = true;
            }
            c = e;
        }
        if (dropped && faces++ == 0) first_line = line_no;
        return true;
    });
    if (faces > 0)
        diag.warning(file_loc(file, first_line),
                     "faces name normals (f v/vt/vn) but the file defines no 'vn': the faces "
                     "are shaded flat from their geometry (" + std::to_string(faces) +
                         " such faces)");
}

std::vector<ShapeStatement> shape_statements(const std::string& text) {
    std::vector<ShapeStatement> found;
    int line_no = 1;
    for (size_t i = 0; i < text.size();) {
        size_t end = i;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
        size_t a = i;
        while (a < end && (text[a] == ' ' || text[a] == '\t')) ++a;
        if (a + 1 < end && (text[a] == 'o' || text[a] == 'g') &&
            (text[a + 1] == ' ' || text[a + 1] == '\t')) {
            size_t b = a + 2, e = end;
            while (b < e && (text[b] == ' ' || text[b] == '\t')) ++b;
            while (e > b && (text[e - 1] == ' ' || text[e - 1] == '\t')) --e;
            found.push_back({text.substr(b, e - b), line_no});
        }
        i = end;
        if (i < text.size() && text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        if (i < text.size()) ++i;
        ++line_no;
    }
    return found;
}

// One pass over the OBJ file: the values of every v, vn and vt statement are numbers, enough
// of them (v x y z [w] or v x y z r g b; vn x y z; vt u [v [w]]).
void check_obj_numbers(const std::string& path, const std::shared_ptr<const std::string>& file) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    Field f[8];
    for (int line_no = 1; std::getline(in, line); ++line_no) {
        size_t a = line.find_first_not_of(" \t");
        if (a == std::string::npos || line[a] != 'v') continue;
        const size_t n = split_fields(line, f);
        const std::string_view key = f[0].text;
        if (key == "v") check_values(f, n, 3, 7, "x y z", file, line_no);
        else if (key == "vn") check_values(f, n, 3, 3, "x y z", file, line_no);
        else if (key == "vt") check_values(f, n, 1, 3, "u", file, line_no);
    }
}

namespace {

// The same for an MTL statement tinyobjloader reads as numbers (its spelling: case matters).
// Returns the number of values of a color statement (1: the MTL spec's gray `Kd 0.5`).
template <size_t N>
size_t check_mtl_numbers(const Field (&f)[N], size_t n,
                         const std::shared_ptr<const std::string>& file, int line_no) {
    const std::string_view key = f[0].text;
    for (const char* k : {"Ka", "Kd", "Ks", "Kt", "Tf", "Ke"})
        if (key == k) {
            if (n == 2) {  // `Kd 0.5` stands for `Kd 0.5 0.5 0.5`
                check_values(f, n, 1, 1, "r g b", file, line_no);
                return 1;
            }
            check_values(f, n, 3, 3, "r g b", file, line_no);
            return 3;
        }
    for (const char* k : {"Ni", "Ns", "d", "Tr", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso",
                          "anisor", "illum"})
        if (key == k) {
            check_values(f, n, 1, 1, "", file, line_no);
            if (key == "illum" && f[1].text.find_first_of(".eE") != std::string_view::npos)
                throw Error(ErrorKind::Scene, file_loc(file, line_no, f[1].column),
                            "'illum' value '" + shown(f[1].text) + "' is not a whole number");
            return 1;
        }
    return 0;
}

}  // namespace

// tinyobjloader only checks face indices against the final counts and names the last line.
// On that error path, find the first face whose index is out of range where it is written
// (OBJ indices are 1-based, negative ones count back from the last element defined so far).
FileLoc locate_bad_index(const std::string& path, const std::shared_ptr<const std::string>& file,
                         std::string* what) {
    std::ifstream in(path);
    std::string line;
    long long nv = 0, nvt = 0, nvn = 0;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        std::istringstream ls(line);
        std::string cmd;
        ls >> cmd;
        if (cmd == "v") ++nv;
        else if (cmd == "vt") ++nvt;
        else if (cmd == "vn") ++nvn;
        else if (cmd == "f" || cmd == "l" || cmd == "p") {
            std::string corner;
            while (ls >> corner) {
                size_t col = line.find(corner) + 1;
                const long long counts[3] = {nv, nvt, nvn};
                const char* names[3] = {"vertex", "texture coordinate", "normal"};
                size_t start = 0;
                for (int k = 0; k < 3 && start <= corner.size(); ++k) {
                    size_t slash = corner.find('/', start);
                    std::string field = corner.substr(start, slash - start);
                    start = slash == std::string::npos ? corner.size() + 1 : slash + 1;
                    if (field.empty()) continue;
                    char* end = nullptr;
                    long long idx = std::strtoll(field.c_str(), &end, 10);
                    if (end == field.c_str() || *end != '\0') {
                        *what = std::string(names[k]) + " index '" + field + "' is not a number";
                        return file_loc(file, line_no, static_cast<int>(col));
                    }
                    long long resolved = idx < 0 ? counts[k] + idx + 1 : idx;
                    if (idx == 0 || resolved < 1 || resolved > counts[k]) {
                        *what = std::string(names[k]) + " index " + field + " is out of range (" +
                                std::to_string(counts[k]) + " defined so far)";
                        return file_loc(file, line_no, static_cast<int>(col));
                    }
                }
            }
        }
    }
    *what = "a face index is out of range";
    return file_loc(file, 0);
}

MtlStatements scan_mtl(const std::vector<std::string>& files) {
    MtlStatements out;
    for (const std::string& f : files) {
        std::ifstream in(f, std::ios::binary);
        std::string line, current;
        bool blender = false, first = true;
        const auto file = std::make_shared<const std::string>(f);
        Field fields[4];
        for (int line_no = 1; std::getline(in, line); ++line_no) {
            if (first && line.rfind("# Blender", 0) == 0) blender = true;
            first = false;
            size_t a = line.find_first_not_of(" \t");
            if (a == std::string::npos || line[a] == '#') continue;
            const size_t n = split_fields(line, fields);
            if (n > 0 && check_mtl_numbers(fields, n, file, line_no) == 1 && n == 2 &&
                fields[0].text.size() == 2 && !current.empty()) {
                std::string k(fields[0].text);
                std::transform(k.begin(), k.end(), k.begin(), ::tolower);
                out.gray[current].insert(k);
            }
            size_t b = line.find_first_of(" \t\r", a);
            std::string key = line.substr(a, b == std::string::npos ? std::string::npos : b - a);
            std::transform(key.begin(), key.end(), key.begin(), ::tolower);
            if (key == "newmtl") {
                size_t s = b == std::string::npos ? line.size() : line.find_first_not_of(" \t", b);
                current = s == std::string::npos ? "" : line.substr(s);
                while (!current.empty() && std::isspace(static_cast<unsigned char>(current.back())))
                    current.pop_back();
                out.keywords[current];
                if (blender) out.blender.insert(current);
            } else if (!current.empty()) {
                out.keywords[current].insert(key);
            }
        }
    }
    return out;
}

}  // namespace glint::obj
