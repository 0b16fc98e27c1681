#include "formats/obj/obj_importer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <map>
#include <set>
#include <iterator>
#include <limits>
#include <sstream>
#include <tuple>

#include <tiny_obj_loader.h>

#include "formats/obj/face_triangulation.h"

namespace glint::obj {
namespace {

namespace fs = std::filesystem;

Color rgb(const tinyobj::real_t* c) { return Color(c[0], c[1], c[2]); }
double average(const Color& c) { return (c.r + c.g + c.b) / 3.0; }

FileLoc file_loc(const std::shared_ptr<const std::string>& file, int line, int column = 1) {
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

// The `o` and `g` statements of the file, in order: each one's name (the rest of its line,
// trimmed, as tinyobjloader names the shape it starts) and line, so that what is said about
// a mesh points at the statement that named it.
struct ShapeStatement {
    std::string name;
    int line = 0;
};

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

// tinyobjloader's MTL reader, noting which files it read: glint reads them once more for what
// tinyobjloader does not keep (which statements were written, who wrote the file).
class MtlFileReader final : public tinyobj::MaterialFileReader {
public:
    explicit MtlFileReader(const std::string& dir) : MaterialFileReader(dir), dir_(dir) {}
    bool operator()(const std::string& id, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warn,
                    std::string* err) override {
        const bool ok = MaterialFileReader::operator()(id, materials, names, warn, err);
        if (ok) files.push_back(dir_.empty() ? id : (fs::path(dir_) / id).string());
        return ok;
    }
    std::vector<std::string> files;

private:
    std::string dir_;
};

// What the MTL files say beyond tinyobjloader's values: the statements each material wrote
// (lowercased keywords), and whether Blender wrote the file (its first line).
// Also checks that the values tinyobjloader reads as numbers are numbers.
struct MtlStatements {
    std::map<std::string, std::set<std::string>> keywords;  // by material name
    std::map<std::string, std::set<std::string>> gray;      // colors given as one value
    std::set<std::string> blender;                          // materials in Blender's files
};

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

scene::PbrMap map_ref(const std::string& name, const tinyobj::texture_option_t& opt,
                      const fs::path& base, const std::string& material, const FileLoc& loc,
                      Diagnostics& diag) {
    scene::PbrMap m;
    if (name.empty()) return m;
    m.file = name;
    m.loc = loc;
    m.offset = Vec3(opt.origin_offset[0], opt.origin_offset[1], opt.origin_offset[2]);
    m.scale = Vec3(opt.scale[0], opt.scale[1], opt.scale[2]);
    m.bump_multiplier = opt.bump_multiplier;
    fs::path p = fs::path(name).is_absolute() ? fs::path(name) : base / name;
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) {
        m.resolved_path = p.string();
    } else {
        diag.warning(loc, "material '" + material + "': texture '" + name +
                              "' not found (looked for " + p.string() +
                              "); the material renders without it");
    }
    return m;
}

// The classic pigment for a PBR base color map: POV-Ray's uv-mapped image_map, bilinear.
void set_image_pigment(scene::Pigment& pig, const scene::PbrMap& map) {
    pig.kind = scene::PatternKind::ImageMap;
    pig.uv_mapping = true;
    scene::ImageMap& im = pig.params.image;
    im.file = map.file;
    im.resolved_path = map.resolved_path;
    std::string ext = fs::path(map.file).extension().string();
    if (!ext.empty()) ext = ext.substr(1);
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    im.type = ext;
    im.map_type = 0;
    im.interpolate = 2;
    im.loc = map.loc;
    // MTL -o/-s: the lookup is at uv * s + o; the pigment transform maps pattern -> uv space.
    Vec3 s(map.scale.x != 0 ? map.scale.x : 1, map.scale.y != 0 ? map.scale.y : 1, 1);
    pig.transform = Transform::translate(Vec3(-map.offset.x, -map.offset.y, 0))
                        .then(Transform::scale(Vec3(1 / s.x, 1 / s.y, 1)));
}

}  // namespace

scene::Material material_from_mtl(const MtlValues& v) {
    scene::Material m;
    scene::Pbr& p = m.pbr;
    p.derived = false;
    p.base_color = v.Kd;
    // Illumination models with refraction (MTL spec: 4, 6, 7, 9 have transparency) and with
    // reflection (3 to 8, where Blender's exporter puts metallic into Ka).
    const bool refracting = v.illum == 4 || v.illum == 6 || v.illum == 7 || v.illum == 9;
    const bool reflecting = v.illum >= 3 && v.illum <= 8;
    if (v.has_Pm) p.metallic = v.Pm;
    else if (v.has_Ka && reflecting) p.metallic = average(v.Ka);
    else p.metallic = 0;
    if (v.has_Pr) {
        p.roughness = v.Pr;
    } else {
        // Inverse of Blender's exporter, Ns = 1000 (1 - roughness)^2; no Ns: no highlight.
        double ns = v.has_Ns ? std::clamp(v.Ns, 0.0, 1000.0) : 0.0;
        p.roughness = 1.0 - std::sqrt(ns / 1000.0);
    }
    p.roughness = std::clamp(p.roughness, 0.0, 1.0);
    p.metallic = std::clamp(p.metallic, 0.0, 1.0);
    p.specular = std::clamp(average(v.Ks), 0.0, 1.0);
    p.ior = v.has_Ni && v.Ni > 0 ? v.Ni : (refracting ? 1.5 : 1.45);
    // Tf is a transmission filter that only refracting models use; many exporters write
    // `Tf 1 1 1` on every opaque material. In the PBR extension (Blender) it is the
    // transmission whatever illum says.
    p.transmission = v.has_Tf && (refracting || v.pbr_extension)
                         ? std::clamp(average(v.Tf), 0.0, 1.0)
                         : 0.0;
    p.emission = v.Ke;
    p.emission_strength = (v.Ke.r > 0 || v.Ke.g > 0 || v.Ke.b > 0) ? 1.0 : 0.0;
    p.alpha = std::clamp(v.d, 0.0, 1.0);
    p.sheen = v.Ps;
    p.clearcoat = v.Pc;
    p.clearcoat_roughness = v.Pcr;
    p.anisotropy = v.aniso;
    p.anisotropy_rotation = v.anisor;

    // The classic half, for the Whitted integrator (MTL.md, "Classic shading").
    scene::Texture& t = m.texture;
    t.pigment.kind = scene::PatternKind::Plain;
    t.pigment.color = scene::ColorFT(v.Kd, p.transmission, 1.0 - p.alpha);
    scene::Finish& f = t.finish;
    f.ambient = Color(0.1, 0.1, 0.1);
    f.emission = v.Ke;
    f.diffuse = 1.0 - p.metallic;
    if (v.Ns > 0 && p.specular > 0) {
        f.phong = p.specular;
        f.phong_size = v.Ns;
    } else {
        f.phong = 0;
    }
    if (p.metallic > 0) {
        f.reflection.min = f.reflection.max = Color(p.metallic, p.metallic, p.metallic);
        f.reflection.metallic = 1;
    }
    if (p.transmission > 0) m.interior.ior = p.ior;
    return m;
}

ObjImport import_obj(const std::string& path, scene::Scene& scene, const Transform& transform,
                     int material_override, Diagnostics& diag) {
    auto file = std::make_shared<const std::string>(path);
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(ErrorKind::MissingFile, FileLoc{}, "cannot open OBJ file '" + path + "'");

    // tinyobjloader's ObjReader::ParseFromFile, with an MTL reader that notes its files.
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    MtlFileReader mtl_reader(fs::path(path).parent_path().string());
    // tinyobjloader reads a value that is not a number as 0: such files are errors.
    check_obj_numbers(path, file);
    bool ok = false;
    std::vector<ShapeStatement> shape_lines;
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error(ErrorKind::MissingFile, FileLoc{}, "cannot open OBJ file '" + path + "'");
        std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        drop_skin_weights(text, file, diag);
        shape_lines = shape_statements(text);
        std::istringstream obj_text(std::move(text));
        ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &obj_text, &mtl_reader,
                              /*triangulate=*/false, /*default_vcols_fallback=*/false);
    }
    if (!ok) {
        if (err.find("Cannot open file") != std::string::npos)
            throw Error(ErrorKind::MissingFile, FileLoc{}, "cannot open OBJ file '" + path + "'");
        if (err.find("face index") != std::string::npos) {
            // tinyobjloader's "zero value for face index" also stands for a non-number.
            std::string what;
            FileLoc l = locate_bad_index(path, file, &what);
            if (l.line > 0) throw Error(ErrorKind::Scene, l, what);
        }
        throw Error(ErrorKind::Scene, file_loc(file, reported_line(err)),
                    "broken OBJ: " + first_line(err));
    }
    // tinyobjloader resolves a negative index that reaches before the first element to a
    // negative position without a warning: every index is checked here.
    bool bad_index = warn.find("indices out of bounds") != std::string::npos;
    const size_t n_pos = attrib.vertices.size() / 3, n_uv = attrib.texcoords.size() / 2,
                 n_nrm = attrib.normals.size() / 3;
    for (const tinyobj::shape_t& sh : shapes)
        for (const tinyobj::index_t& ix : sh.mesh.indices)
            bad_index = bad_index || ix.vertex_index < 0 || size_t(ix.vertex_index) >= n_pos ||
                        ix.texcoord_index >= int(n_uv) || ix.normal_index >= int(n_nrm);
    if (bad_index) {
        std::string what;
        FileLoc l = locate_bad_index(path, file, &what);
        throw Error(ErrorKind::Scene, l, what);
    }
    // A `v 1 nan 0` or `v 1e400 0 0` would reach the renderer as NaN or infinity.
    for (const auto& [values, width, cmd] :
         {std::tuple{&attrib.vertices, 3, "v"}, std::tuple{&attrib.normals, 3, "vn"},
          std::tuple{&attrib.texcoords, 2, "vt"}})
        for (size_t i = 0; i < values->size(); ++i)
            if (!std::isfinite((*values)[i]))
                throw Error(ErrorKind::Scene,
                            file_loc(file, statement_line(path, cmd, i / width)),
                            std::string("'") + cmd + "' statement with a value that is not a "
                            "finite number (NaN, or out of range like 1e400)");
    // Other warnings (a missing .mtl, both d and Tr, ...) go through, one per line.
    std::istringstream ws(warn);
    for (std::string w; std::getline(ws, w);) {
        if (w.empty()) continue;
        diag.warning(file_loc(file, reported_line(w)), w);
    }

    const MtlStatements statements = scan_mtl(mtl_reader.files);

    ObjImport result;
    result.first_material = static_cast<int>(scene.materials.size());
    const fs::path base = fs::path(path).parent_path();
    const FileLoc mtl_loc = file_loc(file, 0);
    for (const tinyobj::material_t& mt : materials) {
        // The statements this material wrote (tinyobjloader gives absent ones its own
        // defaults, 0 for most, so presence comes from glint's own pass over the file).
        static const std::set<std::string> kNone;
        auto found = statements.keywords.find(mt.name);
        const std::set<std::string>& has = found != statements.keywords.end() ? found->second : kNone;
        auto given = [&](const char* k) { return has.count(k) > 0; };
        const bool blender = statements.blender.count(mt.name) > 0;
        auto grays = statements.gray.find(mt.name);
        auto one = [&](const char* k, const tinyobj::real_t* c) {  // `Kd 0.5`: gray
            return grays != statements.gray.end() && grays->second.count(k) ? Color(c[0], c[0], c[0])
                                                                              : rgb(c);
        };
        MtlValues v;
        v.Ka = one("ka", mt.ambient);
        v.has_Ka = given("ka");
        if (given("kd")) v.Kd = one("kd", mt.diffuse);
        v.Ks = one("ks", mt.specular);
        v.Ke = one("ke", mt.emission);
        v.Tf = one(grays != statements.gray.end() && grays->second.count("kt") ? "kt" : "tf", mt.transmittance);
        v.has_Tf = given("tf");
        v.Ns = mt.shininess;
        v.has_Ns = given("ns");
        v.Ni = mt.ior;
        v.has_Ni = given("ni");
        v.d = mt.dissolve;
        v.illum = given("illum") ? mt.illum : 2;
        v.has_Pr = given("pr");
        v.Pr = mt.roughness;
        v.has_Pm = given("pm");
        v.Pm = mt.metallic;
        for (const char* k : {"pr", "pm", "ps", "pc", "pcr", "aniso", "anisor"})
            v.pbr_extension = v.pbr_extension || given(k);
        v.Ps = mt.sheen;
        v.Pc = mt.clearcoat_thickness;
        v.Pcr = mt.clearcoat_roughness;
        v.aniso = mt.anisotropy;
        v.anisor = mt.anisotropy_rotation;
        for (const auto& [name, c] : {std::pair{"Ka", v.Ka}, std::pair{"Kd", v.Kd},
                                      std::pair{"Ks", v.Ks}, std::pair{"Ke", v.Ke},
                                      std::pair{"Tf", v.Tf}})
            if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
                throw Error(ErrorKind::Scene, mtl_loc,
                            "material '" + mt.name + "': " + name +
                                " is not a finite color (NaN, or out of range like 1e400)");
        for (const auto& [name, x] :
             {std::pair{"Ns", v.Ns}, std::pair{"Ni", v.Ni}, std::pair{"d", v.d},
              std::pair{"Pr", v.Pr}, std::pair{"Pm", v.Pm}, std::pair{"Ps", v.Ps},
              std::pair{"Pc", v.Pc}, std::pair{"Pcr", v.Pcr}, std::pair{"aniso", v.aniso},
              std::pair{"anisor", v.anisor}})
            if (!std::isfinite(x))
                throw Error(ErrorKind::Scene, mtl_loc,
                            "material '" + mt.name + "': " + name +
                                " is not a finite number (NaN, or out of range like 1e400)");
        scene::Material m = material_from_mtl(v);
        m.loc = mtl_loc;
        scene::Pbr& p = m.pbr;
        // Blender writes these only for a Principled BSDF (its Diffuse BSDF materials get Pr and
        // Pm alone): the path tracer then uses Principled's Burley diffuse (MTL.md).
        for (const char* k : {"ps", "pc", "pcr", "aniso", "anisor"})
            p.principled = p.principled || given(k);
        auto ref = [&](const std::string& name, const tinyobj::texture_option_t& opt) {
            return map_ref(name, opt, base, mt.name, mtl_loc, diag);
        };
        p.base_color_map = ref(mt.diffuse_texname, mt.diffuse_texopt);
        p.specular_map = ref(mt.specular_texname, mt.specular_texopt);
        p.emission_map = ref(mt.emissive_texname, mt.emissive_texopt);
        p.roughness_map = ref(mt.roughness_texname, mt.roughness_texopt);
        p.metallic_map = ref(mt.metallic_texname, mt.metallic_texopt);
        if (blender && mt.roughness_texname.empty()) {
            // Blender's exporter without PBR extensions writes its roughness image as map_Ns
            // and its metallic image as map_refl (and its importer reads them back so).
            p.roughness_map = ref(mt.specular_highlight_texname, mt.specular_highlight_texopt);
        } else {
            p.exponent_map = ref(mt.specular_highlight_texname, mt.specular_highlight_texopt);
        }
        if (blender && mt.metallic_texname.empty()) {
            // tinyobjloader keeps `map_refl` (it knows `refl`) among unknown parameters.
            auto refl = mt.unknown_parameter.find("map_refl");
            std::string name;
            tinyobj::texture_option_t opt;
            if (refl != mt.unknown_parameter.end() &&
                tinyobj::ParseTextureNameAndOption(&name, &opt, refl->second.c_str()))
                p.metallic_map = ref(name, opt);
        }
        p.alpha_map = ref(mt.alpha_texname, mt.alpha_texopt);
        p.bump_map = ref(mt.bump_texname, mt.bump_texopt);
        if (p.base_color_map.present()) set_image_pigment(m.texture.pigment, p.base_color_map);
        scene.materials.push_back(std::move(m));
    }
    result.material_count = static_cast<int>(materials.size());
    int default_material = -1;
    auto fallback_material = [&]() {
        if (default_material < 0) {
            MtlValues v;  // Blender's default: 0.8 gray, no highlight
            scene::Material m = material_from_mtl(v);
            m.loc = file_loc(file, 0);
            scene.materials.push_back(std::move(m));
            default_material = static_cast<int>(scene.materials.size()) - 1;
            ++result.material_count;
        }
        return default_material;
    };

    // One mesh and one scene object per OBJ object/group, holding only the vertices, normals
    // and uvs its faces use (a remap through index tables reset after each shape).
    const size_t nv = attrib.vertices.size() / 3, nn = attrib.normals.size() / 3,
                 nt = attrib.texcoords.size() / 2;
    std::vector<int> vmap(nv, -1), nmap(nn, -1), tmap(nt, -1);
    std::vector<Vec3> corners;                // of one polygon
    std::vector<std::array<int, 3>> cuts;     // its triangles, as corner indices
    result.first_object = static_cast<int>(scene.objects.size());
    size_t next_statement = 0;
    for (const auto& sh : shapes) {
        scene::Mesh mesh;
        mesh.name = sh.name;
        mesh.loc = file_loc(file, 1);
        for (size_t k = next_statement; k < shape_lines.size() && !sh.name.empty(); ++k) {
            if (shape_lines[k].name == sh.name) {
                mesh.loc = file_loc(file, shape_lines[k].line);
                next_statement = k + 1;
                break;
            }
        }
        std::vector<int> touched_v, touched_n, touched_t;
        auto remap = [](std::vector<int>& map, std::vector<int>& touched, int i, auto add) {
            if (i < 0) return -1;
            if (map[i] < 0) {
                map[i] = add(i);
                touched.push_back(i);
            }
            return map[i];
        };
        auto add_v = [&](int i) {
            mesh.positions.emplace_back(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                                        attrib.vertices[3 * i + 2]);
            result.bounds.extend(transform.point(mesh.positions.back()));
            return static_cast<int>(mesh.positions.size()) - 1;
        };
        auto add_n = [&](int i) {
            mesh.normals.emplace_back(attrib.normals[3 * i], attrib.normals[3 * i + 1],
                                      attrib.normals[3 * i + 2]);
            return static_cast<int>(mesh.normals.size()) - 1;
        };
        auto add_t = [&](int i) {
            mesh.uvs.emplace_back(attrib.texcoords[2 * i], attrib.texcoords[2 * i + 1]);
            return static_cast<int>(mesh.uvs.size()) - 1;
        };
        size_t index = 0;
        const auto& fv = sh.mesh.num_face_vertices;
        mesh.faces.reserve(fv.size());
        for (size_t f = 0; f < fv.size(); ++f) {
            const size_t n = fv[f];
            const tinyobj::index_t* ix = &sh.mesh.indices[index];
            index += n;
            if (n < 3) continue;  // tinyobjloader keeps lines and points apart; none expected
            int mid = f < sh.mesh.material_ids.size() ? sh.mesh.material_ids[f] : -1;
            const int material = material_override >= 0 ? material_override
                                 : mid >= 0 && mid < static_cast<int>(materials.size())
                                     ? result.first_material + mid
                                     : fallback_material();
            cuts.clear();
            if (n == 3) {
                cuts.push_back({0, 1, 2});
            } else {
                corners.resize(n);
                for (size_t k = 0; k < n; ++k) {
                    const size_t vi = static_cast<size_t>(ix[k].vertex_index);
                    corners[k] = Vec3(attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1],
                                      attrib.vertices[3 * vi + 2]);
                }
                triangulate_face(corners, &cuts);
            }
            for (const auto& cut : cuts) {
                scene::MeshFace face;
                bool smooth = true, textured = true;
                for (int k = 0; k < 3; ++k) {
                    const tinyobj::index_t& c = ix[cut[k]];
                    face.v[k] = remap(vmap, touched_v, c.vertex_index, add_v);
                    smooth &= c.normal_index >= 0;
                    textured &= c.texcoord_index >= 0;
                }
                for (int k = 0; k < 3; ++k) {
                    const tinyobj::index_t& c = ix[cut[k]];
                    // Flat unless every corner has a normal; no uvs unless every corner has one.
                    if (smooth) face.n[k] = remap(nmap, touched_n, c.normal_index, add_n);
                    if (textured) face.uv[k] = remap(tmap, touched_t, c.texcoord_index, add_t);
                }
                face.material = material;
                mesh.faces.push_back(face);
            }
        }
        for (int i : touched_v) vmap[i] = -1;
        for (int i : touched_n) nmap[i] = -1;
        for (int i : touched_t) tmap[i] = -1;
        if (mesh.faces.empty()) continue;
        result.triangles += static_cast<long long>(mesh.faces.size());
        int first_face_material = mesh.faces[0].material;
        scene.meshes.push_back(std::move(mesh));
        scene::Object o;
        o.shape = scene::MeshRef{static_cast<int>(scene.meshes.size()) - 1};
        o.transform = transform;
        o.material = first_face_material;
        o.name = sh.name.empty() ? fs::path(path).stem().string() : sh.name;
        o.loc = file_loc(file, 1);
        scene.objects.push_back(std::move(o));
        ++result.object_count;
    }
    if (result.triangles == 0)
        diag.warning(file_loc(file, 0), "OBJ file '" + path + "' has no faces; nothing added");
    return result;
}

scene::Scene viewer_scene(const std::string& path, int width, int height, Diagnostics& diag) {
    scene::Scene scene;
    scene.source_files.push_back(path);
    scene.global.assumed_gamma = 1.0;
    scene.background = scene::ColorFT(Color(0.18, 0.18, 0.2));
    ObjImport im = import_obj(path, scene, Transform::scale(Vec3(1, 1, -1)), -1, diag);
    if (im.triangles == 0)
        throw Error(ErrorKind::Scene, FileLoc{std::make_shared<const std::string>(path), 0, 0},
                    "OBJ file '" + path + "' has no faces: nothing to render");
    Bounds3 b = im.bounds;
    if (b.empty()) b = Bounds3{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
    const Vec3 c = b.centroid();
    double r = 0.5 * length(b.diagonal());
    if (!(r > 0)) r = 1;
    const double aspect = static_cast<double>(width) / height;
    const double vfov = 40.0 * kPi / 180.0;
    const double hfov = 2 * std::atan(std::tan(vfov / 2) * aspect);
    const double fit = std::min(vfov, hfov) / 2;
    const Vec3 view = normalize(Vec3(0.55, 0.45, -1.0));  // from front-right-above
    const double dist = r / std::sin(fit) * 1.05;

    scene::Camera& cam = scene.camera;
    cam.kind = scene::CameraKind::Perspective;
    cam.location = c + view * dist;
    Vec3 dir = normalize(c - cam.location);
    Vec3 right = normalize(cross(Vec3(0, 1, 0), dir));  // POV-Ray's left-handed right
    Vec3 up = cross(dir, right);
    const double h = 2 * std::tan(vfov / 2);
    cam.direction = dir;
    cam.up = up * h;
    cam.right = right * (h * aspect);
    cam.sky = Vec3(0, 1, 0);
    cam.angle = hfov * 180 / kPi;

    auto light = [&](Vec3 offset, double intensity) {
        scene::Light l;
        l.location = c + offset * (3 * r);
        l.color = Color(intensity, intensity, intensity);
        scene.lights.push_back(l);
    };
    light(normalize(Vec3(-0.6, 0.8, -0.7)), 0.9);  // key: upper left, in front
    light(normalize(Vec3(0.9, 0.2, -0.6)), 0.35);  // fill: right, low
    light(normalize(Vec3(0.2, 0.6, 1.0)), 0.45);   // rim: behind
    scene.global.ambient_light = Color(0.6, 0.6, 0.6);
    return scene;
}

}  // namespace glint::obj
