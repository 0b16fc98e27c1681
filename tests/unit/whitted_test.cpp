// The Whitted integrator against closed forms of POV-Ray's classic model: ambient, diffuse
// (kd * I * cos), phong and specular peaks, mirror reflection, shadows (opaque and filtered),
// transmission, trace-level cut-off, background and sky sphere. Geometry is a small analytic
// fake (spheres and one plane) so these tests do not depend on the shape code.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/float.h"
#include "render/integrators/whitted.h"

namespace glint::render {
namespace {

using scene::ColorFT;

struct FakeSphere {
    Vec3 c;
    double r;
    int material;
    uint32_t flags = 0;
};

class FakeGeometry : public Geometry {
public:
    std::vector<FakeSphere> spheres;
    bool has_floor = false;  // plane y = floor_y, normal +y
    double floor_y = 0;
    int floor_material = 0;

    bool intersect(const Ray& ray, Hit* hit) const override {
        bool found = false;
        double best = ray.tmax;
        for (size_t i = 0; i < spheres.size(); ++i) {
            const FakeSphere& s = spheres[i];
            Vec3 oc = ray.origin - s.c;
            double a = dot(ray.dir, ray.dir), b = dot(oc, ray.dir), c = dot(oc, oc) - s.r * s.r;
            double disc = b * b - a * c;
            if (disc < 0) continue;
            double sq = std::sqrt(disc);
            for (double t : {(-b - sq) / a, (-b + sq) / a}) {
                if (t > 1e-9 && t < best) {
                    best = t;
                    found = true;
                    hit->t = t;
                    hit->p = ray.origin + ray.dir * t;
                    hit->ng = hit->n = normalize(hit->p - s.c);
                    hit->material = s.material;
                    hit->flags = s.flags;
                    hit->object = static_cast<int>(i);
                    break;
                }
            }
        }
        if (has_floor && ray.dir.y != 0) {
            double t = (floor_y - ray.origin.y) / ray.dir.y;
            if (t > 1e-9 && t < best) {
                best = t;
                found = true;
                hit->t = t;
                hit->p = ray.origin + ray.dir * t;
                hit->p.y = floor_y;
                hit->ng = hit->n = Vec3(0, 1, 0);
                hit->material = floor_material;
                hit->flags = 0;
                hit->object = static_cast<int>(spheres.size());
            }
        }
        if (found) hit->p_error = abs(hit->p) * 1e-12 + Vec3(1e-12);
        return found;
    }
    bool occluded(const Ray& ray) const override {
        Hit h;
        Ray r = ray;
        while (intersect(r, &h)) {
            if (!(h.flags & kNoShadow)) return true;
            r.origin = offset_ray_origin(h.p, h.p_error, h.ng, r.dir);
            r.tmax -= h.t;
        }
        return false;
    }
    Bounds3 bounds() const override { return Bounds3{Vec3(-1e9), Vec3(1e9)}; }
};

scene::Material matte(Color c, double ambient, double diffuse) {
    scene::Material m;
    m.texture.pigment.color = ColorFT(c);
    m.texture.finish.ambient = Color(ambient);
    m.texture.finish.diffuse = diffuse;
    return m;
}

struct Fixture {
    scene::Scene scene;
    FakeGeometry geo;
    Color render_ray(Vec3 origin, Vec3 dir) {
        // The analyzer learns which materials are used from the objects; give it one
        // stand-in object per material (the fake geometry holds the real shapes).
        scene::Scene s = scene;
        for (size_t i = 0; i < s.materials.size(); ++i) {
            scene::Object o;
            o.material = static_cast<int>(i);
            s.objects.push_back(o);
        }
        auto prepared = prepare(s, RenderOptions{}, std::make_unique<FakeGeometry>(geo));
        Whitted w(*prepared);
        Ray r;
        r.origin = origin;
        r.dir = normalize(dir);
        return w.li(r);
    }
};

void expect_color(const Color& got, const Color& want, double tol = 1e-9) {
    EXPECT_NEAR(got.r, want.r, tol);
    EXPECT_NEAR(got.g, want.g, tol);
    EXPECT_NEAR(got.b, want.b, tol);
}

TEST(Whitted, MissShowsBackground) {
    Fixture fx;
    fx.scene.background = ColorFT(Color(0.1, 0.2, 0.3));
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.1, 0.2, 0.3));
}

TEST(Whitted, AmbientOnly) {
    Fixture fx;
    fx.scene.materials.push_back(matte(Color(1, 0.5, 0.25), 0.3, 0.6));
    fx.scene.global.ambient_light = Color(1, 1, 0.5);
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    // No lights: ambient * ambient_light * pigment.
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.3, 0.15, 0.0375));
}

TEST(Whitted, DiffuseIsKdTimesLightTimesCosine) {
    Fixture fx;
    fx.scene.materials.push_back(matte(Color(0.8, 0.6, 0.4), 0.0, 0.7));
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    scene::Light l;
    l.location = Vec3(0, 0, -10);
    l.color = Color(1, 1, 0.5);
    fx.scene.lights.push_back(l);
    // Facing the light: cos = 1.
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.56, 0.42, 0.14));
    // Light at 60 degrees from the normal of the point (0, 0, -1), far away (parallel).
    fx.scene.lights[0].location = Vec3(0, 1e7 * std::sin(kPi / 3), -1 - 1e7 * std::cos(kPi / 3));
    Color c = fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1));
    EXPECT_NEAR(c.r, 0.56 * 0.5, 1e-6);
}

// irid { 0.5 thickness 0.1 }: each light's contribution times 1 + 0.5 cos(2 pi t (|n.l| +
// |n.e|) / wavelength), POV-Ray's default wavelengths <0.70, 0.52, 0.48>.
TEST(Whitted, IridTintsEachLightByTheFilmPhase) {
    Fixture fx;
    scene::Material m = matte(Color(0.8, 0.6, 0.4), 0.0, 0.7);
    m.texture.finish.irid = 0.5;
    m.texture.finish.irid_thickness = 0.1;
    fx.scene.materials.push_back(m);
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    scene::Light l;
    l.location = Vec3(0, 0, -10);
    l.color = Color(1, 1, 0.5);
    fx.scene.lights.push_back(l);
    const double phase = 2 * kPi * 0.1 * 2;  // light and eye both along the normal
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)),
                 Color(0.56 * (1 + 0.5 * std::cos(phase / 0.70)),
                       0.42 * (1 + 0.5 * std::cos(phase / 0.52)),
                       0.14 * (1 + 0.5 * std::cos(phase / 0.48))));
}

TEST(Whitted, BrillianceRaisesTheCosine) {
    Fixture fx;
    scene::Material m = matte(Color(1, 1, 1), 0.0, 1.0);
    m.texture.finish.brilliance = 3;
    fx.scene.materials.push_back(m);
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    scene::Light l;
    l.parallel = true;
    l.location = Vec3(0, 0, -1) + Vec3(0, std::sin(kPi / 3), -std::cos(kPi / 3)) * 100.0;
    l.point_at = Vec3(0, 0, -1);
    fx.scene.lights.push_back(l);
    Color c = fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1));
    EXPECT_NEAR(c.r, 0.125, 1e-9);  // cos^3 = 0.5^3
}

TEST(Whitted, PhongPeakWhenLightIsBehindTheEye) {
    Fixture fx;
    scene::Material m = matte(Color(0.5, 0.5, 0.5), 0.0, 0.6);
    m.texture.finish.phong = 0.9;
    fx.scene.materials.push_back(m);
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    scene::Light l;
    l.location = Vec3(0, 0, -10);
    fx.scene.lights.push_back(l);
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.5 * 0.6 + 0.9));
}

TEST(Whitted, ShadowlessLightsGiveNoHighlights) {
    Fixture fx;
    scene::Material m = matte(Color(0.5, 0.5, 0.5), 0.0, 0.6);
    m.texture.finish.phong = 0.9;
    m.texture.finish.specular = 0.5;
    fx.scene.materials.push_back(m);
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    scene::Light l;
    l.location = Vec3(0, 0, -10);
    l.shadowless = true;  // POV-Ray's fill light: diffuse only
    fx.scene.lights.push_back(l);
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.5 * 0.6));
}

TEST(Whitted, SpecularPeakAndMetallicTint) {
    Fixture fx;
    scene::Material m = matte(Color(1, 0.5, 0), 0.0, 0.0);
    m.texture.finish.specular = 0.7;
    fx.scene.materials.push_back(m);
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    scene::Light l;
    l.location = Vec3(0, 0, -10);
    fx.scene.lights.push_back(l);
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.7));
    // metallic 1 at normal incidence: POV's Fresnel curve gives F(0) ~ 0 -> surface color.
    fx.scene.materials[0].texture.finish.metallic = 1;
    Color c = fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1));
    double f0 = metallic_fresnel(1.0);
    EXPECT_NEAR(c.g, 0.7 * (1 + (1 - f0) * (0.5 - 1)), 1e-9);
    EXPECT_LT(c.b, c.g);
}

TEST(Whitted, OpaqueShadowLeavesAmbient) {
    Fixture fx;
    fx.scene.materials.push_back(matte(Color(1, 1, 1), 0.1, 0.6));
    fx.geo.has_floor = true;
    fx.geo.spheres.push_back({Vec3(0, 2, 0), 0.5, 0});
    scene::Light l;
    l.location = Vec3(0, 10, 0);
    fx.scene.lights.push_back(l);
    // Floor point (0, 0, 0) straight below the sphere: shadowed.
    expect_color(fx.render_ray(Vec3(0, 1, -1), Vec3(0, -1, 1)), Color(0.1));
    // Floor point (3, 0, 0): lit.
    Color lit = fx.render_ray(Vec3(3, 1, -1), Vec3(0, -1, 1));
    double cosine = 10.0 / std::sqrt(9.0 + 100.0);
    EXPECT_NEAR(lit.r, 0.1 + 0.6 * cosine, 1e-9);
    // no_shadow objects cast none.
    fx.geo.spheres[0].flags = kNoShadow;
    EXPECT_NEAR(fx.render_ray(Vec3(0, 1, -1), Vec3(0, -1, 1)).r, 0.7, 1e-9);
}

TEST(Whitted, AreaLightAveragesItsGridSamples) {
    Fixture fx;
    fx.scene.materials.push_back(matte(Color(1, 1, 1), 0.0, 1.0));
    fx.geo.has_floor = true;
    scene::Light l;
    l.location = Vec3(0, 10, 0);
    l.area = scene::AreaLight{};
    l.area->axis1 = Vec3(2, 0, 0);  // samples at x = -1, 0, 1
    l.area->size1 = 3;
    l.area->size2 = 1;
    fx.scene.lights.push_back(l);
    // Unblocked: the full light.
    EXPECT_NEAR(fx.render_ray(Vec3(0, 1, -1), Vec3(0, -1, 1)).r, 1.0, 1e-9);
    // A small ball hides only the sample at x = -1 from the floor point (0, 0, 0). POV-Ray's
    // corner-and-subdivide averaging then gives (1/2 + 1 + 1/2 + 1) / 4.
    fx.geo.spheres.push_back({Vec3(-0.5, 5, 0), 0.1, 0});
    EXPECT_NEAR(fx.render_ray(Vec3(0, 1, -1), Vec3(0, -1, 1)).r, 0.75, 1e-9);
}

TEST(Whitted, FilteredShadowIsTinted) {
    Fixture fx;
    fx.scene.materials.push_back(matte(Color(1, 1, 1), 0.0, 1.0));
    scene::Material glass = matte(Color(1, 0.5, 0), 0.0, 0.0);
    glass.texture.pigment.color = ColorFT(Color(1, 0.5, 0), 0.8, 0.1);
    fx.scene.materials.push_back(glass);
    fx.geo.has_floor = true;
    fx.geo.spheres.push_back({Vec3(0, 2, 0), 0.5, 1});
    scene::Light l;
    l.location = Vec3(0, 10, 0);
    fx.scene.lights.push_back(l);
    // Two surfaces of the sphere each pass rgb * filter + transmit.
    Color pass(1 * 0.8 + 0.1, 0.5 * 0.8 + 0.1, 0.1);
    Color c = fx.render_ray(Vec3(0, 1, -1), Vec3(0, -1, 1));
    expect_color(c, pass * pass);
}

TEST(Whitted, ReflectionOfBackgroundAndTraceLevel) {
    Fixture fx;
    scene::Material mirror = matte(Color(0, 0, 0), 0.0, 0.0);
    mirror.texture.finish.reflection.min = Color(0.5);
    mirror.texture.finish.reflection.max = Color(0.5);
    fx.scene.materials.push_back(mirror);
    fx.scene.background = ColorFT(Color(0.2, 0.4, 0.8));
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.1, 0.2, 0.4));
    // max_trace_level 1: the reflected ray would be level 2 and returns black.
    fx.scene.global.max_trace_level = 1;
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0));
}

TEST(Whitted, ReflectionFalloffBlendsMinAndMax) {
    Fixture fx;
    scene::Material m = matte(Color(0, 0, 0), 0.0, 0.0);
    m.texture.finish.reflection.min = Color(0.1);
    m.texture.finish.reflection.max = Color(0.9);
    m.texture.finish.reflection.falloff = 2;
    fx.scene.materials.push_back(m);
    fx.scene.background = ColorFT(Color(1, 1, 1));
    fx.geo.has_floor = true;
    // Looking at the floor at 60 degrees from the normal: cos = 0.5, (1 - cos)^2 = 0.25.
    Vec3 dir(0, -std::cos(kPi / 3), std::sin(kPi / 3));
    Color c = fx.render_ray(Vec3(0, 1, 0), dir);
    EXPECT_NEAR(c.r, 0.25 * 0.9 + 0.75 * 0.1, 1e-9);
}

TEST(Whitted, TransmitPassesStraightThroughAtIorOne) {
    Fixture fx;
    scene::Material clear = matte(Color(1, 1, 1), 0.0, 0.0);
    clear.texture.pigment.color = ColorFT(Color(1, 1, 1), 0.0, 1.0);
    fx.scene.materials.push_back(clear);
    fx.scene.background = ColorFT(Color(0.3, 0.6, 0.9));
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0.3, 0.6, 0.9));
}

TEST(Whitted, TransmittedRaysDoNotCountTraceLevels) {
    Fixture fx;
    scene::Material clear = matte(Color(1, 1, 1), 0.0, 0.0);
    clear.texture.pigment.color = ColorFT(Color(1, 1, 1), 0.0, 1.0);
    fx.scene.materials.push_back(clear);
    scene::Material mirror = matte(Color(0, 0, 0), 0.0, 0.0);
    mirror.texture.finish.reflection.min = Color(1);
    mirror.texture.finish.reflection.max = Color(1);
    fx.scene.materials.push_back(mirror);
    fx.scene.background = ColorFT(Color(1, 1, 1));
    fx.scene.global.max_trace_level = 2;
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    fx.geo.has_floor = true;
    fx.geo.floor_y = -2;
    fx.geo.floor_material = 1;
    // Camera ray (level 1) -> through the clear ball (same level) -> mirror floor ->
    // reflected ray (level 2) -> sky. One level more and the reflection would be black.
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, -0.1, 1)), Color(1));
    fx.scene.global.max_trace_level = 1;
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, -0.1, 1)), Color(0));
}

TEST(Whitted, InteriorFadeAttenuatesByDistanceInside) {
    Fixture fx;
    scene::Material glass = matte(Color(1, 1, 1), 0.0, 0.0);
    glass.texture.pigment.color = ColorFT(Color(1, 1, 1), 0.0, 1.0);
    glass.interior.fade_distance = 1;
    glass.interior.fade_power = 2;
    glass.interior.fade_color = Color(0, 0, 0);
    fx.scene.materials.push_back(glass);
    fx.scene.background = ColorFT(Color(1, 1, 1));
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    // Path inside: 2 units -> 1 / (1 + (2/1)^2) = 0.2.
    Color c = fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1));
    EXPECT_NEAR(c.r, 0.2, 1e-9);
    fx.scene.materials[0].interior.fade_power = 1001;  // exponential: exp(-2)
    EXPECT_NEAR(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)).r, std::exp(-2.0), 1e-9);
}

TEST(Whitted, CameraInsideAFadingObjectSeesTheFade) {
    Fixture fx;
    scene::Material glass = matte(Color(1, 1, 1), 0.0, 0.0);
    glass.texture.pigment.color = ColorFT(Color(1, 1, 1), 0.0, 1.0);
    glass.interior.fade_distance = 1;
    glass.interior.fade_power = 2;
    fx.scene.materials.push_back(glass);
    fx.scene.background = ColorFT(Color(1, 1, 1));
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    fx.scene.camera.location = Vec3(0, 0, 0);  // POV-Ray starts such rays inside the ball
    // One unit inside: 1 / (1 + 1^2).
    EXPECT_NEAR(fx.render_ray(Vec3(0, 0, 0), Vec3(0, 0, 1)).r, 0.5, 1e-9);
}

TEST(Whitted, RefractionBendsTowardsTheNormal) {
    Fixture fx;
    scene::Material glass = matte(Color(1, 1, 1), 0.0, 0.0);
    glass.texture.pigment.color = ColorFT(Color(1, 1, 1), 0.0, 1.0);
    glass.interior.ior = 1.5;
    fx.scene.materials.push_back(glass);
    fx.scene.materials.push_back(matte(Color(1, 1, 1), 1.0, 0.0));
    fx.geo.spheres.push_back({Vec3(0, 0, 0), 1, 0});
    // A glass ball focuses the straight-on ray onto the axis: an emitter behind it is seen.
    fx.geo.spheres.push_back({Vec3(0, 0, 5), 0.2, 1});
    expect_color(fx.render_ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(1));
    // A ray off-axis (y = 0.5) bends and misses the small emitter.
    fx.scene.background = ColorFT(Color(0));
    EXPECT_NEAR(fx.render_ray(Vec3(0, 0.5, -5), Vec3(0, 0, 1)).r, 0.0, 1e-12);
}

TEST(Whitted, SpotLightConeAndFade) {
    Fixture fx;
    fx.scene.materials.push_back(matte(Color(1, 1, 1), 0.0, 1.0));
    fx.geo.has_floor = true;
    scene::Light l;
    l.kind = scene::LightKind::Spot;
    l.location = Vec3(0, 10, 0);
    l.point_at = Vec3(0, 0, 0);
    l.radius = 10;
    l.falloff = 20;
    fx.scene.lights.push_back(l);
    // Inside the full cone (0 degrees): full light.
    EXPECT_NEAR(fx.render_ray(Vec3(0, 1, -1), Vec3(0, -1, 1)).r, 1.0, 1e-9);
    // Outside the falloff cone (45 degrees): none.
    EXPECT_NEAR(fx.render_ray(Vec3(10, 1, -1), Vec3(0, -1, 1)).r, 0.0, 1e-12);
    // Light fading: 2 / (1 + (d / fd)^p) with d = 10, fd = 5, p = 2 -> 0.4.
    fx.scene.lights[0].fade_distance = 5;
    fx.scene.lights[0].fade_power = 2;
    EXPECT_NEAR(fx.render_ray(Vec3(0, 1, -1), Vec3(0, -1, 1)).r, 0.4, 1e-9);
}

TEST(Whitted, SkySphereLayersOverBackground) {
    Fixture fx;
    scene::SkySphere sky;
    scene::Pigment bottom;
    bottom.color = ColorFT(Color(0, 0, 1));
    scene::Pigment top;
    top.color = ColorFT(Color(1, 0, 0), 0.0, 0.5);  // half transmitting
    sky.pigments = {bottom, top};
    fx.scene.sky_sphere = sky;
    fx.scene.background = ColorFT(Color(0, 1, 0));
    expect_color(fx.render_ray(Vec3(0, 0, 0), Vec3(0, 0, 1)), Color(0.5, 0, 0.5));
}

}  // namespace
}  // namespace glint::render
