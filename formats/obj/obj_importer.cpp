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
#include "formats/obj/obj_checks.h"

namespace glint::obj {
namespace {

namespace fs = std::filesystem;

Color rgb(const tinyobj::real_t* c) { return Color(c[0], c[1], c[2]); }
double average(const Color& c) { return (c.r + c.g + c.b) / 3.0; }

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
        drop_undefined_normals(text, file, diag);
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
