// The camera, resolved the way POV-Ray 3.7 does for #version >= 3.5 (Parse_Camera in
// source/backend/parser/parse.cpp): modifiers are collected first and then applied in a fixed
// order (right, direction, angle, up, sky, location, look_at, orthographic sizing,
// transforms), so the result does not depend on the order they were written in.
// Also global_settings, background and sky_sphere.
#include <cmath>

#include "formats/pov/parser_impl.h"

namespace glint::pov {

// mesh_camera { rays distribution [max_distance] mesh { ... }... [smooth] } with POV-Ray's
// checks (Parse_Mesh_Camera); the meshes are parsed as objects and kept out of the scene.
void Parser::parse_mesh_camera(scene::MeshCamera& m) {
    expect_open("mesh_camera");
    const FileLoc opened = loc();
    m = scene::MeshCamera{};
    FileLoc at = loc();
    const double rays = parse_float();
    if (!(rays >= 1) || rays > 1e6) fail_at(at, "rays per pixel may not be 0");
    m.rays_per_pixel = static_cast<int>(rays);
    at = loc();
    const double dist = parse_float();
    if (!(dist >= 0) || dist >= 4) fail_at(at, "unrecognized distribution method");
    m.distribution = static_cast<int>(dist);
    if ((m.distribution == 2 || m.distribution == 3) && m.rays_per_pixel != 1)
        fail_at(at, "rays per pixel must be 1 for distribution method #2 or #3");
    m.max_distance = allow_float(0.0);
    for (;;) {
        const Token& t = peek();
        if (!(t.kind == TokKind::Word && (t.text == "mesh" || t.text == "mesh2"))) break;
        const FileLoc kloc = loc();
        const Token kw = next();
        PovObject po;
        parse_object(kw, po);
        const auto* ref = std::get_if<scene::MeshRef>(&po.obj.shape);
        if (!ref) fail_at(kloc, "expected a mesh or mesh2 in the mesh_camera");
        m.meshes.push_back({ref->mesh, po.obj.transform});
    }
    if (accept("smooth")) {
        m.smooth = true;
        if (m.distribution != 3) fail("smooth can only be used with distribution method #3");
    }
    if (m.meshes.empty()) fail("expected mesh or mesh2, got " + got(peek()));
    if (m.distribution == 0 && m.rays_per_pixel > static_cast<int>(m.meshes.size()))
        fail_at(opened, "rays per pixel must be <= number of meshes for distribution method #0");
    if (m.distribution == 3 && m.meshes.size() > 1)
        diag.warning(opened, "additional meshes after the first are ignored for distribution "
                             "method #3");
    expect_close("mesh_camera", opened);
}

void Parser::parse_camera_body(scene::Camera& cam) {
    cam.loc = loc();
    const Token& first = peek();
    if (first.kind == TokKind::Word && lookup(first.text)) {
        const Symbol& s = use_symbol(next());
        auto c = std::get_if<scene::Camera>(&s.value);
        if (!c) fail("expected a camera, got " + value_kind_name(s.value));
        cam = *c;
        // A copied camera only takes transforms (POV-Ray 3.5+).
        Transform tr;
        while (parse_transform_item(tr)) {
        }
        cam.location = tr.point(cam.location);
        cam.direction = tr.vector(cam.direction);
        cam.right = tr.vector(cam.right);
        cam.up = tr.vector(cam.up);
        cam.sky = tr.vector(cam.sky);
        return;
    }
    scene::Camera n = cam;
    std::optional<Vec3> look_at, up, right;
    std::optional<double> angle;
    std::optional<Vec3> focal_point;
    double direction_length = 1;  // Parse_Camera's Direction_Length: the focal default
    Transform tr;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}') || t.kind == TokKind::End) {
            unget();
            break;
        }
        const std::string w = t.kind == TokKind::Word && !lookup(t.text) ? t.text : std::string();
        if (w == "perspective") {
            n.kind = scene::CameraKind::Perspective;
        } else if (w == "orthographic") {
            n.kind = scene::CameraKind::Orthographic;
        } else if (w == "fisheye") {
            n.kind = scene::CameraKind::Fisheye;
        } else if (w == "ultra_wide_angle") {
            n.kind = scene::CameraKind::UltraWideAngle;
        } else if (w == "omnimax") {
            n.kind = scene::CameraKind::Omnimax;
        } else if (w == "panoramic") {
            n.kind = scene::CameraKind::Panoramic;
        } else if (w == "spherical") {
            n.kind = scene::CameraKind::Spherical;
        } else if (w == "cylinder") {
            FileLoc l = loc();
            double type = parse_float();
            static const scene::CameraKind kCyl[] = {
                scene::CameraKind::Cylinder1, scene::CameraKind::Cylinder2,
                scene::CameraKind::Cylinder3, scene::CameraKind::Cylinder4};
            int i = to_int(type);
            if (i < 1 || i > 4)
                fail_at(l, "invalid cylinder camera type " + std::to_string(i) +
                               "; valid types are 1 to 4");
            n.kind = kCyl[i - 1];
        } else if (w == "mesh_camera") {
            n.kind = scene::CameraKind::Mesh;
            parse_mesh_camera(n.mesh_camera);
        } else if (w == "angle") {
            FileLoc l = loc();
            if (n.kind == scene::CameraKind::Spherical) {
                // angle H [, V]: V defaults to half of H (Parse_Camera).
                double h = parse_float();
                if (h < 0) fail_at(l, "negative horizontal angle");
                accept(",");
                double v = allow_float(h * 0.5);
                if (v < 0) fail_at(l, "negative vertical angle");
                n.h_angle = h;
                n.v_angle = v;
                continue;
            }
            double a = n.kind == scene::CameraKind::Orthographic ? allow_float(0) : parse_float();
            if (a < 0) fail_at(l, "negative viewing angle");
            angle = a;
        } else if (w == "location") {
            n.location = parse_vector();
        } else if (w == "look_at") {
            look_at = parse_vector();
        } else if (w == "direction") {
            n.direction = parse_vector();
        } else if (w == "up") {
            up = parse_vector();
        } else if (w == "right") {
            right = parse_vector();
        } else if (w == "sky") {
            n.sky = parse_vector();
        } else if (w == "focal_point") {
            focal_point = parse_vector();
        } else if (w == "aperture" || w == "blur_samples" || w == "confidence" ||
                   w == "variance") {
            parse_focal_blur_item(w, n.focal_blur);
        } else if (w == "normal") {
            // Parse_Tnormal: a camera without a normal starts from the default texture's.
            if (n.normal.kind == scene::PatternKind::Plain) n.normal = default_texture_.normal;
            expect_open("normal");
            const FileLoc lo = loc();
            parse_normal_body(n.normal);
            expect_close("normal", lo);
        } else if (w == "bokeh") {
            warn_unsupported(*this, "camera " + w, loc(), "ignored");
            skip_braced_block(*this, w);
        } else {
            unget();
            Transform delta;
            if (!parse_transform_item(delta))
                fail("expected a camera item (location, look_at, angle, ...), got " +
                     got(next()));
            tr = tr.then(delta);
        }
    }
    if (up) n.up = *up;
    if (right) n.right = *right;
    const bool linear = n.kind == scene::CameraKind::Perspective ||
                        n.kind == scene::CameraKind::Orthographic;
    if (!linear && n.angle == 0) n.angle = 90;  // POV-Ray's Camera::Init default
    if (angle && !linear) {
        n.angle = *angle;  // the non-linear projections use the angle as given
    } else if (angle) {
        FileLoc l = n.loc;
        if (*angle >= 180) fail_at(l, "the viewing angle must be smaller than 180 degrees");
        if (*angle > 0) {
            // direction length so that `right` spans `angle` degrees (parse.cpp).
            double dl = length(n.right) / std::tan(*angle * kPi / 360.0) / 2.0;
            n.direction = normalize(n.direction) * dl;
            direction_length = dl;
        }
        n.angle = *angle;
    }
    Vec3 target = look_at.value_or(Vec3(0, 0, 1));
    if (look_at) {
        double dl = length(n.direction), ul = length(n.up), rl = length(n.right);
        direction_length = dl;
        double handedness = dot(cross(n.up, n.direction), n.right);
        Vec3 d = *look_at - n.location;
        if (length_squared(d) < kPovEpsilon)
            fail_at(n.loc, "the camera location and look_at point must be different");
        n.direction = normalize(d);
        Vec3 saved_right = n.right;
        n.right = cross(n.sky, n.direction);
        if (std::fabs(n.right.x) < kPovEpsilon && std::fabs(n.right.y) < kPovEpsilon &&
            std::fabs(n.right.z) < kPovEpsilon) {
            diag.warning(n.loc, "camera look_at direction and sky are parallel; keeping right");
            n.right = saved_right;
        }
        n.right = normalize(n.right);
        n.up = cross(n.direction, n.right);
        n.direction = n.direction * dl;
        n.right = n.right * (handedness > 0 ? rl : -rl);
        n.up = n.up * ul;
    }
    if (n.kind == scene::CameraKind::Orthographic && ((!up && !right) || angle)) {
        // Size the orthographic view like the perspective one at the look_at distance.
        double k1 = length(target - n.location), k2 = length(n.direction);
        if (k1 > kPovEpsilon && k2 > kPovEpsilon) {
            n.right = n.right * (k1 / k2);
            n.up = n.up * (k1 / k2);
        }
    }
    // The focal distance before the camera's transforms, as Parse_Camera measures it: from
    // the location to focal_point, else the direction's length (0 counts as 1).
    if (focal_point) n.focal_blur.focal_distance = length(*focal_point - n.location);
    else n.focal_blur.focal_distance = direction_length;
    if (n.focal_blur.focal_distance == 0) n.focal_blur.focal_distance = 1;
    n.location = tr.point(n.location);
    n.direction = tr.vector(n.direction);
    n.right = tr.vector(n.right);
    n.up = tr.vector(n.up);
    n.sky = tr.vector(n.sky);
    cam = n;
}

// aperture, blur_samples min[, max], confidence and variance with Parse_Camera's checks.
void Parser::parse_focal_blur_item(const std::string& w, scene::FocalBlur& fb) {
    const FileLoc at = loc();
    if (w == "aperture") {
        fb.aperture = parse_float();
    } else if (w == "blur_samples") {
        // Counts as POV-Ray keeps them (ints); a million bounds the per-pixel work.
        auto count = [&](double v) {
            if (!(v < 1e6 + 1)) fail_at(at, "at most 1000000 focal blur samples");
            return v < 0 ? -1 : static_cast<int>(v);
        };
        const int first = count(parse_float());
        if (first <= 0) fail_at(at, "illegal number of focal blur samples");
        skip_comma();
        const int second = count(allow_float(0.0));
        if (second == 0) {  // one value: the maximum, no minimum
            fb.samples = first;
            fb.samples_min = 0;
        } else {
            if (first > second)
                fail_at(at, "focal blur samples minimum must not be larger than maximum");
            fb.samples_min = first;
            fb.samples = second;
        }
    } else if (w == "confidence") {
        const double v = parse_float();
        if (v > 0 && v < 1) fb.confidence = v;
        else diag.warning(at, "illegal confidence value; the default is used");
    } else {
        const double v = parse_float();
        if (v >= 0 && v <= 1) fb.variance = v;
        else diag.warning(at, "illegal variance value; the default is used");
    }
}

void Parser::parse_global_settings() {
    expect_open("global_settings");
    FileLoc o = loc();
    scene.global.loc = o;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}')) return;
        if (t.kind == TokKind::End) expect_close("global_settings", o);
        const std::string w = t.kind == TokKind::Word ? t.text : std::string();
        if (w == "assumed_gamma") {
            scene.global.assumed_gamma = parse_float();
        } else if (w == "ambient_light") {
            scene.global.ambient_light = parse_rgb();
        } else if (w == "max_trace_level") {
            scene.global.max_trace_level = to_int(parse_float());
        } else if (w == "adc_bailout") {
            scene.global.adc_bailout = parse_float();
        } else if (w == "noise_generator") {
            scene.global.noise_generator = to_int(parse_float());
        } else if (w == "number_of_waves") {
            scene.global.number_of_waves = to_int(parse_float());
        } else if (w == "subsurface") {
            expect_open("subsurface");
            FileLoc so = loc();
            scene.global.subsurface = true;
            for (;;) {
                if (accept("samples")) {
                    scene.global.subsurface_samples_diffuse = to_int(parse_float());
                    skip_comma();
                    scene.global.subsurface_samples_single = to_int(parse_float());
                } else if (accept("radiosity")) {
                    // Radiosity's ambient through the subsurface transport: not modelled.
                    if (parse_float() != 0)
                        diag.warning(loc(), "global_settings subsurface 'radiosity on' is "
                                            "ignored: radiosity lights subsurface finishes "
                                            "as plain ones");
                } else {
                    break;
                }
            }
            expect_close("subsurface", so);
        } else if (w == "mm_per_unit") {
            scene.global.mm_per_unit = parse_float();
        } else if (w == "radiosity") {
            parse_radiosity_settings();
        } else if (w == "photons") {
            parse_photon_settings();
        } else if (w == "charset") {
            diag.warning(loc(), "global_settings 'charset' is ignored");
            next();
        } else if (w == "irid_wavelength") {
            scene.global.irid_wavelength = parse_rgb();
        } else if (w == "max_intersections" || w == "hf_gray_16") {
            diag.warning(loc(), "global_settings '" + w + "' is ignored");
            allow_float(0);
        } else {
            fail("expected a global_settings item (assumed_gamma, max_trace_level, ...), got " +
                 got(t));
        }
    }
}

void Parser::parse_radiosity_settings() {
    // parse.cpp Parse_Global_Settings, RADIOSITY_TOKEN: POV-Ray's checks and messages.
    expect_open("radiosity");
    FileLoc o = loc();
    scene::Radiosity r;
    bool min_set = false, max_set = false;
    FileLoc end_at = o, reuse_at = o;  // where pretrace_end and the reuse values were given
    auto positive = [&](const char* what, double v, bool zero_ok = false) {
        if (zero_ok ? v < 0 : v <= 0)
            fail(std::string("radiosity ") + what + " must be a " +
                 (zero_ok ? "non-negative" : "positive") + " number");
        return v;
    };
    auto in_range = [&](const char* what, double v, int lo, int hi, bool lo_open) {
        if ((lo_open ? v <= lo : v < lo) || v > hi)
            fail(std::string("radiosity ") + what + " must be " +
                 (lo_open ? "greater than " : "at least ") + std::to_string(lo) +
                 " and at most " + std::to_string(hi));
        return v;
    };
    for (;;) {
        FileLoc at;  // the keyword just taken
        auto take = [&](const char* w) { return accept_at(w, &at); };
        if (take("load_file") || take("save_file")) {
            diag.warning(at, "radiosity load_file/save_file is ignored: POV-Ray 3.7 takes "
                             "them on the command line only, and glint keeps no cache file");
            parse_string();
        } else if (take("always_sample")) {
            r.always_sample = parse_float() != 0;
        } else if (take("pretrace_start")) {
            r.pretrace_start = in_range("pretrace_start", parse_float(), 0, 1, true);
        } else if (take("pretrace_end")) {
            end_at = at;
            r.pretrace_end = in_range("pretrace_end", parse_float(), 0, 1, true);
        } else if (take("brightness")) {
            r.brightness = positive("brightness", parse_float());
        } else if (take("count")) {
            // Each gather shoots `count` rays: past a million, a render that never ends (POV-Ray
            // sets no bound). Checked on the floats, before the int conversion.
            const char* too_many =
                "radiosity count and its direction pool must be at most 1000000";
            const double c = parse_float();
            if (!(c >= 1.0)) fail("radiosity count must be a positive number");
            if (c > 1e6) fail_at(at, too_many);
            r.count = static_cast<int>(c);
            skip_comma();
            const double pool = allow_float(std::max(1600, r.count));
            if (pool > 1e6) fail_at(at, too_many);
            if (!(pool >= r.count))
                fail("radiosity count can not be more than its direction pool (count's second "
                     "value)");
            r.direction_pool = static_cast<int>(pool);
        } else if (take("error_bound")) {
            r.error_bound = positive("error_bound", parse_float());
        } else if (take("gray_threshold")) {
            r.gray_threshold = in_range("gray_threshold", parse_float(), 0, 1, false);
        } else if (take("low_error_factor")) {
            r.low_error_factor = positive("low_error_factor", parse_float());
        } else if (take("maximum_reuse")) {
            reuse_at = at;
            r.maximum_reuse = positive("maximum_reuse", parse_float());
            max_set = true;
        } else if (take("minimum_reuse")) {
            reuse_at = at;
            r.minimum_reuse = positive("minimum_reuse", parse_float(), true);
            min_set = true;
        } else if (take("nearest_count")) {
            r.nearest_count = static_cast<int>(in_range("nearest_count", parse_float(), 1, 20, false));
            skip_comma();
            const double apt = allow_float(0);
            if (apt < 0 || static_cast<int>(apt) >= r.nearest_count)
                fail("radiosity nearest_count for adaptive pretrace (its second value) must be "
                     "non-negative and smaller than nearest_count");
            r.nearest_count_pretrace = static_cast<int>(apt);
        } else if (take("recursion_limit")) {
            r.recursion_limit =
                static_cast<int>(in_range("recursion_limit", parse_float(), 1, 20, false));
        } else if (take("max_sample")) {
            r.max_sample = parse_float();
        } else if (take("adc_bailout")) {
            r.adc_bailout = positive("adc_bailout", parse_float());
        } else if (take("normal")) {
            r.normal = parse_float() != 0;
        } else if (take("media")) {
            r.media = parse_float() != 0;
        } else if (take("subsurface")) {
            r.subsurface = parse_float() != 0;
        } else {
            break;
        }
    }
    expect_close("radiosity", o);
    // parse.cpp's end-of-scene checks.
    if (r.pretrace_end > r.pretrace_start)
        fail_at(end_at, "radiosity pretrace_end must be smaller than or equal to pretrace_start");
    if (r.minimum_reuse > r.maximum_reuse * 0.5) {
        if (!min_set) {
            r.minimum_reuse = r.maximum_reuse * 0.5;
        } else if (!max_set) {
            r.maximum_reuse = r.minimum_reuse * 2.0;
        } else if (r.minimum_reuse >= r.maximum_reuse) {
            fail_at(reuse_at, "radiosity maximum_reuse must be larger than minimum_reuse");
        }
    }
    scene.global.radiosity = r;
}

void Parser::parse_photon_settings() {
    // parse.cpp Parse_Global_Settings, PHOTONS_TOKEN.
    expect_open("photons");
    FileLoc o = loc();
    scene::Photons ph;
    ph.loc = o;
    for (;;) {
        FileLoc at;  // the keyword just taken
        auto take = [&](const char* w) { return accept_at(w, &at); };
        if (take("radius")) {
            ph.radius = allow_float(-1);
            skip_comma();
            ph.radius_multiplier = allow_float(1);
            skip_comma();
            ph.media_radius = allow_float(-1);
            skip_comma();
            ph.media_radius_multiplier = allow_float(1);
        } else if (take("spacing")) {
            ph.loc = at;
            ph.spacing = parse_float();
            if (!(ph.spacing > 0)) fail("photons spacing must be positive");
        } else if (take("count")) {
            ph.loc = at;
            ph.count = to_int(parse_float());
            if (ph.count <= 0) fail_at(at, "photons count must be positive");
        } else if (take("expand_thresholds")) {
            ph.expand_tolerance = std::max(0.0, parse_float());
            skip_comma();
            ph.expand_min = std::max(0, to_int(parse_float()));
        } else if (take("gather")) {
            ph.gather_min = to_int(parse_float());
            skip_comma();
            ph.gather_max = to_int(parse_float());
            if (ph.gather_min < 0 || ph.gather_max < 0)
                fail_at(at, "photons gather counts cannot be negative");
            if (ph.gather_min > ph.gather_max)
                fail_at(at, "photons gather: the minimum must be less than the maximum");
        } else if (take("jitter")) {
            ph.jitter = parse_float();
        } else if (take("autostop")) {
            ph.autostop = parse_float();
        } else if (take("adc_bailout")) {
            ph.adc_bailout = parse_float();
        } else if (take("max_trace_level")) {
            ph.max_trace_level = to_int(parse_float());
        } else if (take("load_file")) {
            ph.load_file = parse_string();
        } else if (take("save_file")) {
            ph.save_file = parse_string();
        } else if (take("media")) {
            ph.media_steps = to_int(parse_float());
            if (ph.media_steps < 0) fail("photons media: max media steps must be non-negative");
            skip_comma();
            ph.media_factor = allow_float(1);
            if (!(ph.media_factor > 0)) fail("photons media: the spacing factor must be positive");
        } else {
            break;
        }
    }
    expect_close("photons", o);
    // gather's maximum 0 turns photons off (parse.cpp).
    if (ph.gather_max > 0) scene.global.photons = ph;
}

void Parser::parse_background() {
    expect_open("background");
    FileLoc o = loc();
    scene.background = parse_color();
    // glint writes POV-Ray scenes without alpha (POV-Ray's default, -UA), where POV-Ray
    // settles the background's transmit as it reads it: a 3.7 scene's background is composed
    // over black, an older scene's keeps its colour (the transmit is dropped).
    const double version = version_set() ? this->version() : 3.62;
    scene::ColorFT& bg = scene.background;
    if (version >= 3.7) bg.rgb *= 1.0 - bg.transmit;
    bg.filter = 0;
    bg.transmit = 0;
    expect_close("background", o);
}

void Parser::parse_sky_sphere() {
    expect_open("sky_sphere");
    FileLoc o = loc();
    scene::SkySphere sky;
    sky.loc = o;
    for (;;) {
        const Token& t = next();
        if (t.is_symbol('}')) break;
        if (t.kind == TokKind::End) expect_close("sky_sphere", o);
        if (t.is("pigment")) {
            expect_open("pigment");
            FileLoc po = loc();
            scene::Pigment p;
            p.loc = po;
            parse_pigment_body(p);
            expect_close("pigment", po);
            sky.pigments.push_back(p);
        } else if (t.is("emission")) {
            sky.emission = parse_rgb();
        } else {
            unget();
            Transform delta;
            if (!parse_transform_item(delta))
                fail("expected pigment, emission or a transform in sky_sphere, got " +
                     got(next()));
            sky.transform = sky.transform.then(delta);
        }
    }
    if (sky.pigments.empty()) fail_at(o, "sky_sphere needs at least one pigment");
    scene.sky_sphere = std::move(sky);
}

}  // namespace glint::pov
