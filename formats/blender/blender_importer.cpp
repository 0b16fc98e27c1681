#include "formats/blender/blender_importer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "formats/blender/graph_reader.h"
#include "formats/blender/json_reader.h"

namespace glint::blender {

namespace fs = std::filesystem;

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

Buffers read_buffers(const std::string& path) {
    Buffers b;
    b.path = path;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::MissingFile, {}, "cannot read the scene's buffers: " + path);
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0);
    b.bytes.resize(static_cast<size_t>(std::max<std::streamoff>(size, 0)));
    if (size > 0 && !in.read(reinterpret_cast<char*>(b.bytes.data()), size))
        throw Error(ErrorKind::MissingFile, {}, "cannot read the scene's buffers: " + path);
    return b;
}

Vec3 column(const Matrix4& m, int c) { return {m.m[0][c], m.m[1][c], m.m[2][c]}; }

// One mesh of the exchange with its faces' slots (material_index) still unresolved.
struct MeshSource {
    scene::Mesh mesh;
    std::vector<uint16_t> slots;  // per face
    int max_slot = 0;
};

MeshSource read_mesh(const JsonReader& r, const Buffers& buf,
                     const std::shared_ptr<const std::string>& file, bool motion_blur) {
    using T = BufferView::Type;
    MeshSource src;
    scene::Mesh& m = src.mesh;
    m.name = r.string("name", "");
    m.loc.file = file;
    const BufferView pos = read_view(r.at("positions"), buf, 3, {T::F32});
    const BufferView loop_vertex = read_view(r.at("loop_vertex"), buf, 1, {T::U32});
    const BufferView tris = read_view(r.at("triangles"), buf, 3, {T::U32});
    m.positions.resize(pos.count);
    for (size_t i = 0; i < pos.count; ++i) {
        m.positions[i] = {pos.get(i, 0), pos.get(i, 1), pos.get(i, 2)};
        if (!is_finite(m.positions[i])) r.at("positions").fail("a position is not finite");
    }
    const size_t loops = loop_vertex.count;
    std::vector<int> vertex_of(loops);
    for (size_t i = 0; i < loops; ++i) {
        const uint32_t v = loop_vertex.index(i);
        if (v >= pos.count)
            r.at("loop_vertex").fail("corner " + std::to_string(i) + " names vertex " +
                                     std::to_string(v) + " of " + std::to_string(pos.count));
        vertex_of[i] = static_cast<int>(v);
    }
    bool has_normals = r.has("normals");
    if (has_normals) {
        const BufferView nv = read_view(r.at("normals"), buf, 3, {T::F32});
        if (nv.count != loops) r.at("normals").fail("expected one normal per corner");
        m.normals.resize(loops);
        for (size_t i = 0; i < loops; ++i) {
            Vec3 n{nv.get(i, 0), nv.get(i, 1), nv.get(i, 2)};
            m.normals[i] = is_finite(n) && length_squared(n) > 0 ? normalize(n) : Vec3(0, 0, 1);
        }
    }
    // Deformation motion blur: the positions (and split normals) at each motion step.
    if (motion_blur && r.has("motion")) {
        const JsonReader steps = r.at("motion");
        if (steps.size() < 2) steps.fail("expected two or more motion steps");
        for (size_t k = 0; k < steps.size(); ++k) {
            const JsonReader step = steps.at(k);
            const BufferView sp = read_view(step.at("positions"), buf, 3, {T::F32});
            if (sp.count != pos.count) step.at("positions").fail("expected one position per vertex");
            std::vector<Vec3>& ps = m.motion_positions.emplace_back(sp.count);
            for (size_t i = 0; i < sp.count; ++i) {
                ps[i] = {sp.get(i, 0), sp.get(i, 1), sp.get(i, 2)};
                if (!is_finite(ps[i])) step.at("positions").fail("a position is not finite");
            }
            if (!has_normals) continue;
            if (!step.has("normals")) step.fail("expected normals, as the mesh has");
            const BufferView sn = read_view(step.at("normals"), buf, 3, {T::F32});
            if (sn.count != loops) step.at("normals").fail("expected one normal per corner");
            std::vector<Vec3>& ns = m.motion_normals.emplace_back(sn.count);
            for (size_t i = 0; i < sn.count; ++i) {
                const Vec3 n{sn.get(i, 0), sn.get(i, 1), sn.get(i, 2)};
                ns[i] = is_finite(n) && length_squared(n) > 0 ? normalize(n) : Vec3(0, 0, 1);
            }
        }
    }
    // The active render UV map is the mesh's uv; every layer is also an attribute by name
    // (the UV Map and Attribute nodes), as is every colour attribute.
    if (r.has("uv_layers")) {
        const JsonReader layers = r.at("uv_layers");
        int chosen = -1;
        for (size_t k = 0; k < layers.size(); ++k)
            if (chosen < 0 || layers.at(k).boolean("active_render", false))
                chosen = static_cast<int>(k);
        for (size_t k = 0; k < layers.size(); ++k) {
            const JsonReader layer = layers.at(k);
            const BufferView uv = read_view(layer.at("data"), buf, 2, {T::F32});
            if (uv.count != loops) layer.at("data").fail("expected one uv per corner");
            if (static_cast<int>(k) == chosen) {
                m.uvs.resize(loops);
                for (size_t i = 0; i < loops; ++i) m.uvs[i] = {uv.get(i, 0), uv.get(i, 1)};
            }
            scene::MeshAttribute a;
            a.name = layer.string("name", "");
            a.kind = scene::MeshAttribute::Kind::UV;
            a.active_render = static_cast<int>(k) == chosen;
            a.values.resize(loops);
            for (size_t i = 0; i < loops; ++i) a.values[i] = {uv.get(i, 0), uv.get(i, 1), 0};
            m.attributes.push_back(std::move(a));
        }
    }
    // MikkTSpace tangents of the UV maps a Normal Map node reads, per triangle corner.
    if (r.has("tangents")) {
        const JsonReader layers = r.at("tangents");
        for (size_t k = 0; k < layers.size(); ++k) {
            const JsonReader layer = layers.at(k);
            const BufferView t = read_view(layer.at("tangent"), buf, 3, {T::F32});
            const BufferView s = read_view(layer.at("sign"), buf, 1, {T::F32});
            const size_t corners = 3 * tris.count;
            if (t.count != corners)
                layer.at("tangent").fail("expected one tangent per triangle corner");
            if (s.count != corners) layer.at("sign").fail("expected one sign per triangle corner");
            scene::MeshAttribute a;
            a.name = layer.string("uv_map", "");
            a.kind = scene::MeshAttribute::Kind::Tangent;
            a.active_render = layer.boolean("active_render", false);
            a.per_triangle_corner = true;
            a.values.resize(corners);
            a.alpha.resize(corners);
            for (size_t i = 0; i < corners; ++i) {
                const Vec3 v{t.get(i, 0), t.get(i, 1), t.get(i, 2)};
                a.values[i] = is_finite(v) ? v : Vec3();
                const double sign = s.get(i, 0);
                a.alpha[i] = std::isfinite(sign) ? static_cast<float>(sign) : 1.0f;
            }
            m.attributes.push_back(std::move(a));
        }
    }
    if (r.has("colors")) {
        const JsonReader layers = r.at("colors");
        for (size_t k = 0; k < layers.size(); ++k) {
            const JsonReader layer = layers.at(k);
            const BufferView c = read_view(layer.at("data"), buf, 4, {T::F32});
            const std::string domain = layer.string("domain", "CORNER");
            const bool point = domain == "POINT";
            if (!point && domain != "CORNER")
                layer.at("domain").fail("expected POINT or CORNER, not " + domain);
            if (c.count != (point ? pos.count : loops))
                layer.at("data").fail(point ? "expected one colour per vertex"
                                            : "expected one colour per corner");
            scene::MeshAttribute a;
            a.name = layer.string("name", "");
            a.kind = scene::MeshAttribute::Kind::Color;
            a.active_render = layer.boolean("active_render", false);
            a.values.resize(loops);
            a.alpha.resize(loops);
            for (size_t i = 0; i < loops; ++i) {
                const size_t at = point ? static_cast<size_t>(vertex_of[i]) : i;
                a.values[i] = {c.get(at, 0), c.get(at, 1), c.get(at, 2)};
                a.alpha[i] = static_cast<float>(c.get(at, 3));
            }
            m.attributes.push_back(std::move(a));
        }
    }
    // Generated coordinates' space: the add-on's, else Blender's automatic one (the bounds;
    // a flat dimension gets size 1, as BKE_mesh_texspace_calc gives it).
    if (r.has("texspace")) {
        const JsonReader ts = r.at("texspace");
        m.texspace_location = ts.vec3("location", Vec3(0, 0, 0));
        m.texspace_size = ts.vec3("size", Vec3(1, 1, 1));
    } else if (!m.positions.empty()) {
        Vec3 lo = m.positions[0], hi = m.positions[0];
        for (const Vec3& p : m.positions) lo = min(lo, p), hi = max(hi, p);
        m.texspace_location = (lo + hi) * 0.5;
        m.texspace_size = (hi - lo) * 0.5;
    }
    for (int k = 0; k < 3; ++k)
        if (m.texspace_size[k] == 0) m.texspace_size[k] = 1;
        else if (m.texspace_size[k] > 0 && m.texspace_size[k] < 1e-5) m.texspace_size[k] = 1e-5;
    m.has_texspace = true;
    std::vector<uint8_t> smooth;
    if (r.has("smooth")) {
        const BufferView s = read_view(r.at("smooth"), buf, 1, {T::U8});
        if (s.count != tris.count) r.at("smooth").fail("expected one value per triangle");
        smooth.resize(s.count);
        for (size_t i = 0; i < s.count; ++i) smooth[i] = static_cast<uint8_t>(s.index(i));
    }
    if (r.has("material_index")) {
        const BufferView s = read_view(r.at("material_index"), buf, 1, {T::U16, T::U8, T::U32});
        if (s.count != tris.count) r.at("material_index").fail("expected one value per triangle");
        src.slots.resize(s.count);
        for (size_t i = 0; i < s.count; ++i) {
            src.slots[i] = static_cast<uint16_t>(std::min<uint32_t>(s.index(i), 65535));
            src.max_slot = std::max<int>(src.max_slot, src.slots[i]);
        }
    }
    m.faces.resize(tris.count);
    if (!m.attributes.empty()) m.corners.resize(tris.count);
    for (size_t t = 0; t < tris.count; ++t) {
        scene::MeshFace& f = m.faces[t];
        for (int c = 0; c < 3; ++c) {
            const uint32_t l = tris.index(t, c);
            if (l >= loops)
                r.at("triangles").fail("triangle " + std::to_string(t) + " names corner " +
                                       std::to_string(l) + " of " + std::to_string(loops));
            f.v[c] = vertex_of[l];
            const bool flat = !smooth.empty() && smooth[t] == 0;
            f.n[c] = has_normals && !flat ? static_cast<int>(l) : -1;
            f.uv[c] = m.uvs.empty() ? -1 : static_cast<int>(l);
            if (!m.corners.empty()) m.corners[t][static_cast<size_t>(c)] = static_cast<int>(l);
        }
    }
    return src;
}

// A panoramic camera as Cycles 3.4 syncs it (blender/camera.cpp): the settings of
// camera.cycles, the sensor fitted to the image for the equisolid and polynomial fisheyes, and
// a frame of unit vectors (Cycles clears the matrix's scale and ignores the shift).
void read_panorama(const JsonReader& r, double wx, double wy, const Vec3& X, const Vec3& Y,
                   const Vec3& Z, scene::Camera* c) {
    using scene::PanoramaType;
    static const std::pair<const char*, PanoramaType> kTypes[] = {
        {"EQUIRECTANGULAR", PanoramaType::Equirectangular},
        {"FISHEYE_EQUIDISTANT", PanoramaType::FisheyeEquidistant},
        {"FISHEYE_EQUISOLID", PanoramaType::FisheyeEquisolid},
        {"MIRRORBALL", PanoramaType::MirrorBall},
        {"FISHEYE_LENS_POLYNOMIAL", PanoramaType::FisheyeLensPolynomial},
        {"EQUIANGULAR_CUBEMAP_FACE", PanoramaType::EquiangularCubemapFace},
    };
    scene::Panorama& p = c->panorama;
    const std::string name = r.string("panorama_type", "FISHEYE_EQUISOLID");
    bool known = false;
    for (const auto& [n, t] : kTypes)
        if (name == n) p.type = t, known = true;
    if (!known)
        r.at("panorama_type").fail("panorama type '" + name + "' (EQUIRECTANGULAR, "
                                   "FISHEYE_EQUIDISTANT, FISHEYE_EQUISOLID, MIRRORBALL, "
                                   "FISHEYE_LENS_POLYNOMIAL, EQUIANGULAR_CUBEMAP_FACE)");
    p.fov = r.number("fisheye_fov", kPi);
    p.lens = r.number("fisheye_lens", 10.5);
    p.latitude_min = r.number("latitude_min", -kPi / 2);
    p.latitude_max = r.number("latitude_max", kPi / 2);
    p.longitude_min = r.number("longitude_min", -kPi);
    p.longitude_max = r.number("longitude_max", kPi);
    static const char* const kCoefficients[] = {"fisheye_polynomial_k0", "fisheye_polynomial_k1",
                                                "fisheye_polynomial_k2", "fisheye_polynomial_k3",
                                                "fisheye_polynomial_k4"};
    static const double kDefaults[] = {-1.1735143743862864e-05, -0.019988736137747765,
                                       -3.3525323033245513e-06, 3.0992753181635635e-06,
                                       -2.60646473293491e-08};  // Blender 3.4's
    for (int i = 0; i < 5; ++i) p.k[i] = r.number(kCoefficients[i], kDefaults[i]);
    // The sensor: AUTO fits the sensor width to the longer side (Cycles: strictly wider is
    // horizontal), VERTICAL the sensor height to the image height.
    const std::string fit = r.string("sensor_fit", "AUTO");
    const bool horizontal = fit == "AUTO" ? wx > wy : fit == "HORIZONTAL";
    const double size =
        fit == "VERTICAL" ? r.number("sensor_height", 24) : r.number("sensor_width", 36);
    p.sensor_width = horizontal ? size : size * wx / wy;
    p.sensor_height = horizontal ? size * wy / wx : size;
    c->kind = scene::CameraKind::BlenderPanorama;
    c->direction = -Z;
    c->right = X;
    c->up = Y;
}

// Blender's camera (BKE_camera_params_compute_viewplane): the fit dimension spans
// sensor / lens at unit distance (ortho: ortho_scale), the shift is in units of it.
// Motion blur's matrices (`motion`: two or more, in shutter order).
std::vector<Matrix4> read_motion(const JsonReader& r) {
    const JsonReader list = r.at("motion");
    if (list.size() < 2) list.fail("expected two or more matrices");
    std::vector<Matrix4> out;
    for (size_t i = 0; i < list.size(); ++i) out.push_back(list.at(i).matrix());
    return out;
}

// Cycles' camera ignores the matrix's scale (transform_clear_scale): its axes normalized.
Matrix4 clear_scale(Matrix4 m) {
    for (int k = 0; k < 3; ++k) {
        const double len = std::sqrt(m.m[0][k] * m.m[0][k] + m.m[1][k] * m.m[1][k] +
                                     m.m[2][k] * m.m[2][k]);
        if (len > 0)
            for (int i = 0; i < 3; ++i) m.m[i][k] /= len;
    }
    return m;
}

scene::Camera read_camera(const JsonReader& r, int width, int height, double aspx, double aspy,
                          bool motion_blur) {
    scene::Camera c;
    const Matrix4 m = r.matrix("matrix");
    if (motion_blur && r.has("motion")) {
        c.centre = clear_scale(m);
        for (const Matrix4& step : read_motion(r)) c.motion.push_back(clear_scale(step));
    }
    const Vec3 X = normalize(column(m, 0)), Y = normalize(column(m, 1)),
               Z = normalize(column(m, 2));
    const Vec3 loc = column(m, 3);
    const std::string type = r.string("type", "PERSP");
    const double lens = r.number("lens", 50);
    const double sensor_x = r.number("sensor_width", 36), sensor_y = r.number("sensor_height", 24);
    std::string fit = r.string("sensor_fit", "AUTO");
    const double wx = width * aspx, wy = height * aspy;
    if (fit == "AUTO") fit = wx >= wy ? "HORIZONTAL_AUTO" : "VERTICAL_AUTO";
    const double sensor = fit == "VERTICAL" ? sensor_y : sensor_x;
    const bool horizontal = fit == "HORIZONTAL" || fit == "HORIZONTAL_AUTO";
    const double ycor = aspy / aspx;
    const double viewfac = horizontal ? width : ycor * height;
    const double span = type == "ORTHO" ? r.number("ortho_scale", 6) : sensor / lens;
    const double w = width * span / viewfac, h = ycor * height * span / viewfac;
    const double shift_x = r.number("shift_x", 0) * span, shift_y = r.number("shift_y", 0) * span;
    c.location = loc;
    c.sky = Y;
    if (type == "ORTHO") {
        c.kind = scene::CameraKind::Orthographic;
        c.location = loc + X * shift_x + Y * shift_y;
        c.direction = -Z;
    } else {
        c.kind = scene::CameraKind::Perspective;
        c.direction = -Z + X * shift_x + Y * shift_y;
    }
    c.right = X * w;
    c.up = Y * h;
    c.clip_start = std::max(0.0, r.number("clip_start", 0));
    c.clip_end = std::max(c.clip_start, r.number("clip_end", kInfinity));
    if (type == "PANO") read_panorama(r, wx, wy, X, Y, Z, &c);
    if (r.has("dof") && r.at("dof").boolean("use", false)) {
        const JsonReader d = r.at("dof");
        const double fstop = d.number("fstop", 2.8);
        if (fstop > 0 && std::isfinite(fstop)) {
            // Cycles (blender/camera.cpp): half the focal length over the f-number, the
            // focal length in metres; an orthographic camera's aperture is 1 / (2 fstop) mm.
            c.lens.radius = type == "ORTHO" ? 0.5e-3 / fstop : 0.5 * lens * 1e-3 / fstop;
            c.lens.focal_distance = std::max(d.number("focus_distance", 10), 1e-5);
            c.lens.blades = std::max(0, d.integer("blades", 0));
            if (c.lens.blades < 3) c.lens.blades = 0;
            c.lens.rotation = d.number("rotation", 0);
            c.lens.ratio = d.number("ratio", 1);
            if (!(c.lens.ratio > 0)) c.lens.ratio = 1;
        }
    }
    return c;
}

scene::Light read_light(const JsonReader& r, Diagnostics& diag, const FileLoc& loc) {
    scene::Light l;
    scene::BlenderLight b;
    const Matrix4 m = r.matrix("matrix");
    const std::string name = r.string("name", "");
    const std::string type = r.string("type", "POINT");
    if (type == "POINT") b.type = scene::BlenderLightType::Point;
    else if (type == "SPOT") b.type = scene::BlenderLightType::Spot;
    else if (type == "SUN") b.type = scene::BlenderLightType::Sun;
    else if (type == "AREA") b.type = scene::BlenderLightType::Area;
    else r.at("type").fail("light type '" + type + "' (POINT, SPOT, SUN, AREA)");
    l.location = column(m, 3);
    l.color = r.color("color", Color(1, 1, 1));
    const Vec3 dir = -column(m, 2);
    b.direction = length_squared(dir) > 0 ? normalize(dir) : Vec3(0, 0, -1);
    b.power = r.number("energy", 10);
    b.radius = r.number("shadow_soft_size", 0.25);
    b.spot_size = r.number("spot_size", 0.785398) * kRadToDeg;
    b.spot_blend = r.number("spot_blend", 0.15);
    b.angle = r.number("angle", 0.00918043) * kRadToDeg;
    const std::string shape = r.string("shape", "SQUARE");
    b.ellipse = shape == "DISK" || shape == "ELLIPSE";
    const double size = r.number("size", 0.25);
    const double size_y = shape == "RECTANGLE" || shape == "ELLIPSE" ? r.number("size_y", size) : size;
    const Vec3 ax = column(m, 0), ay = column(m, 1);
    b.size_x = size * length(ax);
    b.size_y = size_y * length(ay);
    b.axis_x = length_squared(ax) > 0 ? normalize(ax) : Vec3(1, 0, 0);
    b.axis_y = length_squared(ay) > 0 ? normalize(ay) : Vec3(0, 1, 0);
    b.spread = r.number("spread", 3.14159265358979) * kRadToDeg;
    if (r.has("visibility")) b.visible_camera = r.at("visibility").boolean("camera", false);
    if (b.power < 0) {
        diag.warning(loc, "light '" + name + "': negative power is not supported: left out");
        b.power = 0;
    }
    if (!r.boolean("cast_shadow", true))
        diag.warning(loc, "light '" + name + "': Cast Shadow off is not supported: rendered with shadows");
    l.blender = b;
    l.loc = loc;
    return l;
}

}  // namespace

bool is_blender_exchange(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return ext == ".json";
}

scene::Scene import_blender(const std::string& path, const ImportLimits& limits,
                            Diagnostics& diag) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::MissingFile, {}, "cannot read scene file: " + path);
    std::stringstream text;
    text << in.rdbuf();
    const std::string content = text.str();
    auto file = std::make_shared<const std::string>(path);
    Json root;
    try {
        root = Json::parse(content);
    } catch (const Json::parse_error& e) {
        // Its byte offset as line:col, for the caret under the line.
        FileLoc loc;
        loc.file = file;
        loc.line = 1;
        loc.column = 1;
        const size_t end = std::min<size_t>(e.byte > 0 ? e.byte - 1 : 0, content.size());
        for (size_t i = 0; i < end; ++i) {
            if (content[i] == '\n') ++loc.line, loc.column = 1;
            else ++loc.column;
        }
        std::string what = e.what();
        const size_t colon = what.rfind(": ");
        if (colon != std::string::npos) what = what.substr(colon + 2);
        throw Error(ErrorKind::Scene, loc, "JSON syntax: " + what);
    }
    const JsonReader r(root, "", file);
    if (r.string("format", "") != "glint-blender")
        r.fail("not a glint Blender exchange (\"format\": \"glint-blender\" expected)");
    if (r.integer("version", 0) != 1)
        r.at("version").fail("version " + std::to_string(r.integer("version", 0)) +
                             " is not supported (this glint reads version 1)");
    const std::string dir = fs::path(path).parent_path().string();
    Buffers buf;
    if (r.has("buffers")) {
        std::string bin = r.at("buffers").string();
        if (fs::path(bin).is_relative()) bin = (fs::path(dir) / bin).string();
        buf = read_buffers(bin);
    }
    FileLoc loc;
    loc.file = file;

    scene::Scene scene;
    scene.version = 3.7;
    scene.source_files.push_back(path);
    scene.global.assumed_gamma = 1.0;
    scene.global.ambient_light = Color(0, 0, 0);

    scene::BlenderRender settings;
    const JsonReader render = r.at("render");
    settings.width = render.at("width").integer();
    settings.height = render.at("height").integer();
    if (settings.width < 1 || settings.height < 1) render.fail("the image size must be positive");
    settings.samples = std::max(1, render.integer("samples", 64));
    settings.seed = render.integer("seed", 0);
    if (render.has("max_bounces")) {
        const JsonReader b = render.at("max_bounces");
        settings.max_bounces = b.integer("total", settings.max_bounces);
        settings.diffuse_bounces = b.integer("diffuse", settings.diffuse_bounces);
        settings.glossy_bounces = b.integer("glossy", settings.glossy_bounces);
        settings.transmission_bounces = b.integer("transmission", settings.transmission_bounces);
        settings.transparent_bounces = b.integer("transparent", settings.transparent_bounces);
        settings.volume_bounces = b.integer("volume", settings.volume_bounces);
    }
    settings.film_transparent = render.boolean("film_transparent", false);
    settings.volume_step_rate = render.number("volume_step_rate", 1.0);
    if (!(settings.volume_step_rate > 0)) settings.volume_step_rate = 1.0;
    settings.volume_max_steps = std::clamp(render.integer("volume_max_steps", 1024), 2, 65536);
    settings.filter_width = render.number("filter_width", 1.5);
    settings.pixel_filter = render.string("pixel_filter", "BLACKMAN_HARRIS");
    if (render.has("adaptive_sampling")) {
        const auto& a = render.at("adaptive_sampling");
        settings.adaptive_sampling = a.boolean("use", false);
        settings.adaptive_threshold = std::max(0.0, a.number("threshold", 0.01));
        settings.adaptive_min_samples = std::max(0, a.integer("min_samples", 0));
    }
    settings.clamp_direct = render.number("clamp_direct", 0);
    settings.clamp_indirect = render.number("clamp_indirect", 10);
    settings.filter_glossy = render.number("filter_glossy", 1);
    settings.caustics_reflective = render.boolean("caustics_reflective", true);
    settings.caustics_refractive = render.boolean("caustics_refractive", true);
    if (settings.film_transparent && render.boolean("film_transparent_glass", false))
        settings.film_transparent_glass =
            std::max(0.0, render.number("film_transparent_roughness", 0.1));
    scene.blender_render = settings;
    // Motion blur: the camera's and objects' `motion` matrices are read only with it on.
    const bool motion_blur =
        render.has("motion_blur") && render.at("motion_blur").boolean("use", false);

    double aspx = 1, aspy = 1;
    if (r.has("camera")) {
        const JsonReader cam = r.at("camera");
        if (cam.has("pixel_aspect")) {
            const std::vector<double> a = cam.at("pixel_aspect").numbers();
            if (a.size() >= 2 && a[0] > 0 && a[1] > 0) aspx = a[0], aspy = a[1];
        }
        scene.camera = read_camera(cam, settings.width, settings.height, aspx, aspy, motion_blur);
        scene.camera.loc = loc;
    } else {
        r.fail("the scene has no camera");
    }

    // Materials: each a graph; the Cycles default surface for slots without one.
    std::vector<int> material_ids;
    if (r.has("materials")) {
        const JsonReader mats = r.at("materials");
        for (size_t i = 0; i < mats.size(); ++i) {
            const JsonReader mj = mats.at(i);
            scene::Material mat;
            mat.loc = loc;
            mat.pbr.derived = false;
            const std::string name = mj.string("name", "material " + std::to_string(i));
            if (mj.has("graph") && !mj.at("graph").is_null()) {
                scene.shader_graphs.push_back(read_graph(mj.at("graph"), name, dir));
                scene.shader_graphs.back().loc = loc;
                mat.graph = static_cast<int>(scene.shader_graphs.size()) - 1;
            }
            if (mj.has("cycles")) {
                const JsonReader cy = mj.at("cycles");
                mat.volume_step_rate = cy.number("volume_step_rate", 1.0);
                if (!(mat.volume_step_rate > 0)) mat.volume_step_rate = 1.0;
                mat.volume_homogeneous = cy.boolean("homogeneous_volume", false);
                const std::string method = cy.string("displacement_method", "BUMP");
                if (method != "BUMP")
                    diag.warning(loc, "material '" + name + "': displacement method " + method +
                                          " moves no geometry in glint: rendered as bump only");
            }
            scene.materials.push_back(std::move(mat));
            material_ids.push_back(static_cast<int>(scene.materials.size()) - 1);
        }
    }
    int default_surface = -1;
    auto default_material = [&]() {
        if (default_surface < 0) {
            // Cycles' surface for objects without a material: a Diffuse BSDF, 0.8 grey.
            scene::Material mat;
            mat.loc = loc;
            mat.pbr.derived = false;
            mat.pbr.base_color = Color(0.8, 0.8, 0.8);
            mat.pbr.specular = 0;
            mat.pbr.roughness = 0;
            scene.materials.push_back(std::move(mat));
            default_surface = static_cast<int>(scene.materials.size()) - 1;
        }
        return default_surface;
    };

    // Meshes, held once each; an object's slots become the faces' materials. Objects that
    // share a mesh but map its slots differently (object-linked materials) get a copy each.
    std::vector<MeshSource> sources;
    long long triangles = 0;
    if (r.has("meshes")) {
        const JsonReader meshes = r.at("meshes");
        for (size_t i = 0; i < meshes.size(); ++i) {
            sources.push_back(read_mesh(meshes.at(i), buf, file, motion_blur));
            triangles += static_cast<long long>(sources.back().mesh.faces.size());
            if (triangles > limits.triangles)
                throw Error(ErrorKind::Render, loc,
                            "the scene has more than " + std::to_string(limits.triangles) +
                                " mesh triangles (limit: --max-triangles)");
        }
    }
    std::map<std::pair<int, std::vector<int>>, int> mesh_for;  // (source, slot materials) -> IR mesh
    if (r.has("objects")) {
        const JsonReader objects = r.at("objects");
        if (static_cast<long long>(objects.size()) > limits.objects)
            throw Error(ErrorKind::Render, loc,
                        "the scene has " + std::to_string(objects.size()) +
                            " objects, more than " + std::to_string(limits.objects) +
                            " (limit: --max-objects)");
        scene.objects.reserve(objects.size());
        for (size_t i = 0; i < objects.size(); ++i) {
            const JsonReader oj = objects.at(i);
            const int src = oj.at("mesh").integer();
            if (src < 0 || src >= static_cast<int>(sources.size()))
                oj.at("mesh").fail("no mesh " + std::to_string(src));
            std::vector<int> slots;
            if (oj.has("materials"))
                for (size_t k = 0; k < oj.at("materials").size(); ++k) {
                    const int id = oj.at("materials").at(k).integer();
                    if (id >= static_cast<int>(material_ids.size()))
                        oj.at("materials").at(k).fail("no material " + std::to_string(id));
                    slots.push_back(id < 0 ? -1 : material_ids[id]);
                }
            // Slots past the list (and empty ones) render with the default surface.
            const MeshSource& s = sources[src];
            std::vector<int> resolved(static_cast<size_t>(s.max_slot) + 1);
            for (size_t k = 0; k < resolved.size(); ++k) {
                // Cycles clamps a face's slot to the object's last material slot.
                const size_t slot = slots.empty() ? 0 : std::min(k, slots.size() - 1);
                const int id = slot < slots.size() ? slots[slot] : -1;
                resolved[k] = id >= 0 ? id : default_material();
            }
            auto key = std::make_pair(src, resolved);
            auto it = mesh_for.find(key);
            int mesh_id;
            if (it != mesh_for.end()) {
                mesh_id = it->second;
            } else {
                scene::Mesh mesh = s.mesh;
                if (resolved.size() > 1)
                    for (size_t f = 0; f < mesh.faces.size(); ++f)
                        mesh.faces[f].material = resolved[s.slots.empty() ? 0 : s.slots[f]];
                scene.meshes.push_back(std::move(mesh));
                mesh_id = static_cast<int>(scene.meshes.size()) - 1;
                mesh_for.emplace(std::move(key), mesh_id);
            }
            scene::Object o;
            o.shape = scene::MeshRef{mesh_id};
            o.material = resolved[0];
            const Matrix4 matrix = oj.matrix("matrix");
            Matrix4 inverse;
            if (!matrix.inverse(&inverse)) continue;  // scaled to nothing: Blender shows nothing
            o.transform = Transform(matrix, inverse);
            if (motion_blur && oj.has("motion")) o.motion = read_motion(oj);
            o.name = oj.string("name", "");
            o.loc = loc;
            if (oj.has("visibility")) {
                const JsonReader v = oj.at("visibility");
                o.visibility.camera = v.boolean("camera", true);
                o.visibility.diffuse = v.boolean("diffuse", true);
                o.visibility.glossy = v.boolean("glossy", true);
                o.visibility.transmission = v.boolean("transmission", true);
                o.visibility.shadow = v.boolean("shadow", true);
            }
            o.no_image = !o.visibility.camera;
            o.no_shadow = !o.visibility.shadow;
            o.holdout = oj.boolean("holdout", false);
            o.info_color = oj.color("color", Color(1, 1, 1));
            o.pass_index = oj.number("pass_index", 0);
            o.random = oj.number("random", 0);
            if (oj.has("volume")) {
                // A Volume object: the box of its grids, shaded by its OpenVDB file.
                const JsonReader v = oj.at("volume");
                scene::Object::VolumeFile vf;
                vf.path = v.at("file").string();
                if (fs::path(vf.path).is_relative()) vf.path = (fs::path(dir) / vf.path).string();
                vf.step_size = v.number("step_size", 0);
                vf.object_space = v.string("space", "OBJECT") != "WORLD";
                o.volume_file = std::move(vf);
            }
            scene.objects.push_back(std::move(o));
        }
    }
    // Meshes nobody instanced are dropped above; the sources go now.
    sources.clear();

    if (r.has("lights")) {
        const JsonReader lights = r.at("lights");
        for (size_t i = 0; i < lights.size(); ++i) {
            scene::Light l = read_light(lights.at(i), diag, loc);
            if (l.blender->power > 0) scene.lights.push_back(std::move(l));
        }
    }

    if (r.has("world")) {
        const JsonReader w = r.at("world");
        if (w.has("graph") && !w.at("graph").is_null()) {
            scene.shader_graphs.push_back(read_graph(w.at("graph"), "world", dir));
            scene.shader_graphs.back().loc = loc;
            scene.world_graph = static_cast<int>(scene.shader_graphs.size()) - 1;
            if (w.has("cycles")) {
                const JsonReader cy = w.at("cycles");
                scene.world_volume_step = cy.number("volume_step_size", 1.0);
                if (!(scene.world_volume_step > 0)) scene.world_volume_step = 1.0;
                scene.world_volume_homogeneous = cy.boolean("homogeneous_volume", false);
            }
        } else {
            scene.background = scene::ColorFT(w.color("color", Color(0.05, 0.05, 0.05)));
        }
    }
    return scene;
}

}  // namespace glint::blender
