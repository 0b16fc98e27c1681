// The Sky Texture node as Cycles 3.4 computes it; see sky_nodes.h. Reimplemented from the
// formulas of Blender 3.4's intern/sky (sky_model.cpp, sky_nishita.cpp),
// intern/cycles/scene/shader_nodes.cpp (SkyTextureNode) and intern/cycles/kernel/svm/sky.h,
// with the same constants and the same single/double precision choices.
#include "render/shader/sky_nodes.h"

#include <algorithm>
#include <cmath>

#include "render/shader/converter_nodes.h"

namespace glint::render::shader {

// sky_hosek_data.cpp
extern const double kHosekXyzConfig[3][2][10][6][9];
extern const double kHosekXyzRadiance[3][2][10][6];

bool parse_sky_type(std::string_view id, SkyType* out) {
    if (id == "PREETHAM") {
        *out = SkyType::PREETHAM;
    } else if (id == "HOSEK_WILKIE") {
        *out = SkyType::HOSEK_WILKIE;
    } else if (id == "NISHITA") {
        *out = SkyType::NISHITA;
    } else {
        return false;
    }
    return true;
}

namespace {

// Cycles' float constants (M_PI_F, M_PI_2_F, M_2PI_F).
constexpr float kPi = 3.1415926535897932f;
constexpr float kHalfPi = 1.5707963267948966f;
constexpr float kTwoPi = 6.2831853071795864f;

float sqr(float v) { return v * v; }
float sum(float3 v) { return v.x + v.y + v.z; }

// ---- Cycles kernel helpers -----------------------------------------------------------------

float clamped_acos(float v) { return std::acos(std::clamp(v, -1.0f, 1.0f)); }

// Cycles 3.4's direction_to_spherical: theta from +Z, phi = atan2(x, y).
struct Spherical {
    float theta, phi;
};
Spherical to_spherical(float3 d) { return {clamped_acos(d.z), std::atan2(d.x, d.y)}; }

// Angle between two unit vectors, accurate at small angles (Cycles' precise_angle).
float angle_between(float3 a, float3 b) { return 2.0f * std::atan2(len(a - b), len(a + b)); }

float3 lerp(float3 a, float3 b, float t) { return a + t * (b - a); }

// XYZ -> scene linear, negative components set to zero (Cycles' xyz_to_rgb_clamped).
float3 xyz_to_scene_linear(float3 xyz) {
    return {std::max(dot(kCyclesXyzToRgb.r, xyz), 0.0f),
            std::max(dot(kCyclesXyzToRgb.g, xyz), 0.0f),
            std::max(dot(kCyclesXyzToRgb.b, xyz), 0.0f)};
}

// Angle between the directions (theta, phi) and (theta2, phi2) (Cycles' sky_angle_between).
float spherical_angle(float theta, float phi, float theta2, float phi2) {
    const float c = std::sin(theta) * std::sin(theta2) * std::cos(phi2 - phi) +
                    std::cos(theta) * std::cos(theta2);
    return clamped_acos(c);
}

// ---- Preetham --------------------------------------------------------------------------------

// Perez et al.'s five-parameter luminance distribution.
float perez(const float* p, float theta, float gamma) {
    const float cg = std::cos(gamma);
    return (1.0f + p[0] * std::exp(p[1] / std::cos(theta))) *
           (1.0f + p[2] * std::exp(p[3] * gamma) + p[4] * cg * cg);
}

// ---- Hosek-Wilkie ----------------------------------------------------------------------------

// The model's radiance distribution for one channel (evaluated in float, as the kernel does).
float hosek_distribution(const float* c, float theta, float gamma) {
    const float cos_theta = std::cos(theta);
    const float cos_gamma = std::cos(gamma);
    const float exp_term = std::exp(c[4] * gamma);
    const float ray_term = cos_gamma * cos_gamma;
    const float mie_term =
        (1.0f + ray_term) / std::pow(1.0f + c[8] * c[8] - 2.0f * c[8] * cos_gamma, 1.5f);
    const float zenith_term = std::sqrt(cos_theta);
    return (1.0f + c[0] * std::exp(c[1] / (cos_theta + 0.01f))) *
           (c[2] + c[3] * exp_term + c[5] * ray_term + c[6] * mie_term + c[7] * zenith_term);
}

// Quintic Bezier blend of six control values at s in [0, 1] (the published model's
// elevation interpolation, term by term as Blender evaluates it).
double bezier5(const double* v, int stride, double s) {
    const double r = 1.0 - s;
    return std::pow(r, 5.0) * v[0] + 5.0 * std::pow(r, 4.0) * s * v[stride] +
           10.0 * std::pow(r, 3.0) * std::pow(s, 2.0) * v[2 * stride] +
           10.0 * std::pow(r, 2.0) * std::pow(s, 3.0) * v[3 * stride] +
           5.0 * r * std::pow(s, 4.0) * v[4 * stride] + std::pow(s, 5.0) * v[5 * stride];
}

// Bilinear blend over (albedo 0/1) x (turbidity floor/ceil) of a per-(albedo, turbidity) value
// (Blender's cooking order: the two albedos at the lower turbidity, then at the upper one
// unless the turbidity is 10).
template <typename F>
double blend_albedo_turbidity(double turbidity, double albedo, F value) {
    const int t = static_cast<int>(turbidity);
    const double frac = turbidity - static_cast<double>(t);
    double res = (1.0 - albedo) * (1.0 - frac) * value(0, t - 1);
    res += albedo * (1.0 - frac) * value(1, t - 1);
    if (t == 10) {
        return res;
    }
    res += (1.0 - albedo) * frac * value(0, t);
    res += albedo * frac * value(1, t);
    return res;
}

// ---- Nishita (single scattering, Blender's intern/sky) ---------------------------------------

constexpr float kRayleighScale = 8e3f;  // scale height (m)
constexpr float kMieScale = 1.2e3f;     // scale height (m)
constexpr float kMieCoeff = 2e-5f;      // scattering coefficient (1/m)
constexpr float kMieG = 0.76f;          // aerosol anisotropy
constexpr float kMieG2 = kMieG * kMieG;
constexpr float kEarthRadius = 6360e3f;       // m
constexpr float kAtmosphereRadius = 6420e3f;  // m
constexpr int kViewSteps = 32;                // segments along the view ray
constexpr int kWavelengths = 21;              // 380 .. 780 nm
constexpr float kWavelengthStep = 20.0f;      // nm

// Per wavelength (380, 400, .. 780 nm): solar irradiance at the top of the atmosphere
// (W m^-2 nm^-1), Rayleigh scattering and ozone absorption coefficients (1/m), CIE 1931 XYZ.
constexpr float kIrradiance[kWavelengths] = {
    1.45756829855592995315f, 1.56596305559738380175f, 1.65148449067670455293f,
    1.71496242737209314555f, 1.75797983805020541226f, 1.78256407885924539336f,
    1.79095108475838560302f, 1.78541550133410664714f, 1.76815554864306845317f,
    1.74122069647250410362f, 1.70647127164943679389f, 1.66556087452739887134f,
    1.61993437242451854274f, 1.57083597368892080581f, 1.51932335059305478886f,
    1.46628494965214395407f, 1.41245852740172450623f, 1.35844961970384092709f,
    1.30474913844739281998f, 1.25174963272610817455f, 1.19975998755420620867f};
constexpr float kRayleighCoeff[kWavelengths] = {
    0.00005424820087636473f, 0.00004418549866505454f, 0.00003635151910165377f,
    0.00003017929012024763f, 0.00002526320226989157f, 0.00002130859310621843f,
    0.00001809838025320633f, 0.00001547057129129042f, 0.00001330284977336850f,
    0.00001150184784075764f, 0.00000999557429990163f, 0.00000872799973630707f,
    0.00000765513700977967f, 0.00000674217203751443f, 0.00000596134125832052f,
    0.00000529034598065810f, 0.00000471115687557433f, 0.00000420910481110487f,
    0.00000377218381260133f, 0.00000339051255477280f, 0.00000305591531679811f};
constexpr float kOzoneCoeff[kWavelengths] = {
    0.00000000325126849861f, 0.00000000585395365047f, 0.00000001977191155085f,
    0.00000007309568762914f, 0.00000020084561514287f, 0.00000040383958096161f,
    0.00000063551335912363f, 0.00000096707041180970f, 0.00000154797400424410f,
    0.00000209038647223331f, 0.00000246128056164565f, 0.00000273551299461512f,
    0.00000215125863128643f, 0.00000159051840791988f, 0.00000112356197979857f,
    0.00000073527551487574f, 0.00000046450130357806f, 0.00000033096079921048f,
    0.00000022512612292678f, 0.00000014879129266490f, 0.00000016828623364192f};
constexpr float kCmf[kWavelengths][3] = {{0.00136800000f, 0.00003900000f, 0.00645000100f},
                                         {0.01431000000f, 0.00039600000f, 0.06785001000f},
                                         {0.13438000000f, 0.00400000000f, 0.64560000000f},
                                         {0.34828000000f, 0.02300000000f, 1.74706000000f},
                                         {0.29080000000f, 0.06000000000f, 1.66920000000f},
                                         {0.09564000000f, 0.13902000000f, 0.81295010000f},
                                         {0.00490000000f, 0.32300000000f, 0.27200000000f},
                                         {0.06327000000f, 0.71000000000f, 0.07824999000f},
                                         {0.29040000000f, 0.95400000000f, 0.02030000000f},
                                         {0.59450000000f, 0.99500000000f, 0.00390000000f},
                                         {0.91630000000f, 0.87000000000f, 0.00165000100f},
                                         {1.06220000000f, 0.63100000000f, 0.00080000000f},
                                         {0.85444990000f, 0.38100000000f, 0.00019000000f},
                                         {0.44790000000f, 0.17500000000f, 0.00002000000f},
                                         {0.16490000000f, 0.06100000000f, 0.00000000000f},
                                         {0.04677000000f, 0.01700000000f, 0.00000000000f},
                                         {0.01135916000f, 0.00410200000f, 0.00000000000f},
                                         {0.00289932700f, 0.00104700000f, 0.00000000000f},
                                         {0.00069007860f, 0.00024920000f, 0.00000000000f},
                                         {0.00016615050f, 0.00006000000f, 0.00000000000f},
                                         {0.00004150994f, 0.00001499000f, 0.00000000000f}};

// Optical depth towards the top of the atmosphere by 8-point Gauss-Laguerre quadrature over
// the ray scaled to length 25 (nodes / 25; weights with exp(node) folded in, / 25).
constexpr int kQuadratureSteps = 8;
constexpr float kQuadratureNodes[kQuadratureSteps] = {
    0.006811185292f, 0.03614807107f, 0.09004346519f, 0.1706680068f,
    0.2818362161f,   0.4303406404f,  0.6296271457f,  0.9145252695f};
constexpr float kQuadratureWeights[kQuadratureSteps] = {
    0.01750893642f, 0.04135477391f, 0.06678839063f, 0.09507698807f,
    0.1283416365f,  0.1707430204f,  0.2327233347f,  0.3562490486f};

// Latitude/longitude to a unit vector (longitude from +X towards +Y).
float3 geographic_direction(float lat, float lon) {
    return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

float3 spectrum_to_xyz(const float* spectrum) {
    float3 xyz(0.0f);
    for (int i = 0; i < kWavelengths; i++) {
        xyz.x += kCmf[i][0] * spectrum[i];
        xyz.y += kCmf[i][1] * spectrum[i];
        xyz.z += kCmf[i][2] * spectrum[i];
    }
    return xyz * kWavelengthStep;
}

// Relative densities at a height above sea level: (Rayleigh, Mie, ozone); ozone is a tent
// between 10 and 40 km peaking at 25 km.
float3 densities(float height) {
    float ozone = 0.0f;
    if (height >= 10000.0f && height < 25000.0f) {
        ozone = 1.0f / 15000.0f * height - 2.0f / 3.0f;
    } else if (height >= 25000.0f && height < 40000.0f) {
        ozone = -(1.0f / 15000.0f * height - 8.0f / 3.0f);
    }
    return {std::exp(-height / kRayleighScale), std::exp(-height / kMieScale), ozone};
}

float rayleigh_phase(float mu) { return 3.0f / (16.0f * kPi) * (1.0f + sqr(mu)); }

float mie_phase(float mu) {
    return (3.0f * (1.0f - kMieG2) * (1.0f + sqr(mu))) /
           (8.0f * kPi * (2.0f + kMieG2) * std::pow(1.0f + kMieG2 - 2.0f * kMieG * mu, 1.5f));
}

// Whether the ray from pos along dir hits the ground sphere.
bool hits_ground(float3 pos, float3 dir) {
    if (dir.z >= 0.0f) {
        return false;
    }
    const float b = -2.0f * dot(dir, -pos);
    const float c = dot(pos, pos) - sqr(kEarthRadius);
    return b * b - 4.0f * c >= 0.0f;
}

// Where the ray from pos (inside the atmosphere) along dir leaves it.
float3 atmosphere_exit(float3 pos, float3 dir) {
    const float b = -2.0f * dot(dir, -pos);
    const float c = dot(pos, pos) - sqr(kAtmosphereRadius);
    const float t = (-b + std::sqrt(b * b - 4.0f * c)) / 2.0f;
    return {pos.x + dir.x * t, pos.y + dir.y * t, pos.z + dir.z * t};
}

// Optical depth factors (Rayleigh, Mie, ozone) from origin to the top of the atmosphere.
float3 optical_depth_to_space(float3 origin, float3 dir) {
    const float length = len(origin - atmosphere_exit(origin, dir));
    const float3 segment = length * dir;
    float3 depth(0.0f);
    for (int i = 0; i < kQuadratureSteps; i++) {
        const float3 p = origin + kQuadratureNodes[i] * segment;
        depth += densities(len(p) - kEarthRadius) * kQuadratureWeights[i];
    }
    return depth * length;
}

struct Atmosphere {
    float3 density_scale;  // (air, dust, ozone)
};

// Single-scattered sunlight along a view ray, per wavelength.
void scatter_along_ray(float3 view_dir, float3 sun_dir, float3 origin, const Atmosphere& atm,
                       float* spectrum) {
    const float ray_length = len(origin - atmosphere_exit(origin, view_dir));
    const float step_length = ray_length / kViewSteps;
    const float3 step = step_length * view_dir;
    for (int w = 0; w < kWavelengths; w++) {
        spectrum[w] = 0.0f;
    }
    const float mu = dot(view_dir, sun_dir);
    const float3 phase(rayleigh_phase(mu), mie_phase(mu), 0.0f);

    float3 view_depth(0.0f);
    float3 p = origin + 0.5f * step;  // each segment is sampled at its middle
    for (int i = 0; i < kViewSteps; i++) {
        const float3 density = atm.density_scale * densities(len(p) - kEarthRadius);
        view_depth += step_length * density;
        if (!hits_ground(p, sun_dir)) {
            const float3 total =
                view_depth + atm.density_scale * optical_depth_to_space(p, sun_dir);
            for (int w = 0; w < kWavelengths; w++) {
                const float3 extinction =
                    total * float3(kRayleighCoeff[w], 1.11f * kMieCoeff, kOzoneCoeff[w]);
                const float transmittance = std::exp(-sum(extinction));
                const float3 scattering = density * float3(kRayleighCoeff[w], kMieCoeff, 0.0f);
                spectrum[w] +=
                    transmittance * sum(phase * scattering) * kIrradiance[w] * step_length;
            }
        }
        p += step;
    }
}

// Blender's SKY_nishita_skymodel_precompute_texture over the whole table: rows at latitudes
// growing quadratically from the horizon, columns at longitudes -pi + 2 pi x / width for the
// first half, mirrored onto the second half.
std::vector<float3> nishita_table(float sun_elevation, float altitude, const Atmosphere& atm) {
    constexpr int w = SkyModel::kTableWidth;
    constexpr int h = SkyModel::kTableHeight;
    std::vector<float3> table(static_cast<size_t>(w) * h);
    const float3 origin(0.0f, 0.0f, kEarthRadius + altitude);
    const float3 sun_dir = geographic_direction(sun_elevation, 0.0f);
    const float lat_step = kHalfPi / h;
    const float lon_step = kTwoPi / w;
    float spectrum[kWavelengths];
    for (int y = 0; y < h; y++) {
        const float lat = (kHalfPi + lat_step / 2.0f) * sqr(static_cast<float>(y) / h);
        for (int x = 0; x < w / 2; x++) {
            const float lon = lon_step * static_cast<float>(x) - kPi;
            scatter_along_ray(geographic_direction(lat, lon), sun_dir, origin, atm, spectrum);
            const float3 xyz = spectrum_to_xyz(spectrum);
            table[static_cast<size_t>(y) * w + x] = xyz;
            table[static_cast<size_t>(y) * w + (w - 1 - x)] = xyz;
        }
    }
    return table;
}

// Radiance of the sun disc seen along elevation angle `elevation` (XYZ), attenuated by air and
// dust only, spread over the disc's solid angle.
float3 sun_radiance(float elevation, float altitude, float air, float dust, float solid_angle) {
    const float3 origin(0.0f, 0.0f, kEarthRadius + altitude);
    const float3 depth = optical_depth_to_space(origin, geographic_direction(elevation, 0.0f));
    float spectrum[kWavelengths];
    for (int i = 0; i < kWavelengths; i++) {
        const float tau = kRayleighCoeff[i] * depth.x * air + 1.11f * kMieCoeff * depth.y * dust;
        spectrum[i] = kIrradiance[i] * std::exp(-tau) / solid_angle;
    }
    return spectrum_to_xyz(spectrum);
}

}  // namespace

// ---- Preparation (Cycles' sync/compile) ------------------------------------------------------

SkyModel SkyModel::prepare(const SkyParams& params) {
    SkyModel m;
    m.type_ = params.type;
    if (params.type == SkyType::PREETHAM || params.type == SkyType::HOSEK_WILKIE) {
        // Blender normalizes the direction at sync; Cycles takes acos(z), atan2(x, y).
        const float3 sun = safe_normalize(params.sun_direction);
        const float theta = std::acos(std::clamp(sun.z, -1.0f, 1.0f));
        m.sun_phi_ = std::atan2(sun.x, sun.y);
        if (params.type == SkyType::PREETHAM) {
            m.sun_theta_ = theta;
            const float t = params.turbidity;
            const float t2 = t * t;
            const float th2 = theta * theta;
            const float th3 = th2 * theta;
            // Zenith luminance (kcd/m^2, scaled) and chromaticity.
            const float chi = (4.0f / 9.0f - t / 120.0f) * (kPi - 2.0f * theta);
            float zenith_lum = (4.0453f * t - 4.9710f) * std::tan(chi) - 0.2155f * t + 2.4192f;
            zenith_lum *= 0.06f;
            const float zenith_x =
                (0.00166f * th3 - 0.00375f * th2 + 0.00209f * theta) * t2 +
                (-0.02903f * th3 + 0.06377f * th2 - 0.03202f * theta + 0.00394f) * t +
                (0.11693f * th3 - 0.21196f * th2 + 0.06052f * theta + 0.25886f);
            const float zenith_y =
                (0.00275f * th3 - 0.00610f * th2 + 0.00317f * theta) * t2 +
                (-0.04214f * th3 + 0.08970f * th2 - 0.04153f * theta + 0.00516f) * t +
                (0.15346f * th3 - 0.26756f * th2 + 0.06670f * theta + 0.26688f);
            // Perez coefficients A..E for Y, x, y (linear in turbidity).
            const float coef[3][5][2] = {
                {{0.1787f, -1.4630f},
                 {-0.3554f, 0.4275f},
                 {-0.0227f, 5.3251f},
                 {0.1206f, -2.5771f},
                 {-0.0670f, 0.3703f}},
                {{-0.0193f, -0.2592f},
                 {-0.0665f, 0.0008f},
                 {-0.0004f, 0.2125f},
                 {-0.0641f, -0.8989f},
                 {-0.0033f, 0.0452f}},
                {{-0.0167f, -0.2608f},
                 {-0.0950f, 0.0092f},
                 {-0.0079f, 0.2102f},
                 {-0.0441f, -1.6537f},
                 {-0.0109f, 0.0529f}},
            };
            const float zenith[3] = {zenith_lum, zenith_x, zenith_y};
            for (int c = 0; c < 3; c++) {
                for (int i = 0; i < 5; i++) {
                    m.config_[c][i] = coef[c][i][0] * t + coef[c][i][1];
                }
                // Normalize so that the zenith (theta 0, sun at gamma = theta) gives the
                // zenith value.
                m.scale_[c] = zenith[c] / perez(m.config_[c], 0.0f, theta);
            }
        } else {
            // Cycles clamps to [0, 10]; Blender's property range starts at 1, the lowest the
            // data covers (NaN is taken as 1).
            const float turbidity = std::fmin(std::fmax(params.turbidity, 1.0f), 10.0f);
            const float sun_theta = std::clamp(theta, 0.0f, kHalfPi);
            m.sun_theta_ = sun_theta;
            const double elevation = static_cast<double>(kHalfPi - sun_theta);
            const double s = std::pow(elevation / (3.141592653589793 / 2.0), 1.0 / 3.0);
            const double albedo = params.ground_albedo;
            for (int c = 0; c < 3; c++) {
                for (int i = 0; i < 9; i++) {
                    const double v = blend_albedo_turbidity(turbidity, albedo, [&](int a, int t) {
                        return bezier5(&kHosekXyzConfig[c][a][t][0][i], 9, s);
                    });
                    m.config_[c][i] = static_cast<float>(v);
                }
                const double r = blend_albedo_turbidity(turbidity, albedo, [&](int a, int t) {
                    return bezier5(&kHosekXyzRadiance[c][a][t][0], 1, s);
                });
                m.scale_[c] = static_cast<float>(r);
            }
        }
        return m;
    }

    // NISHITA.
    const float altitude = std::clamp(params.altitude, 1.0f, 59999.0f);
    const float diameter = std::max(params.sun_size, 0.0005f);
    const float half = diameter / 2.0f;
    const float solid_angle = kTwoPi * (1.0f - std::cos(half));
    const float bottom = params.sun_elevation - half;
    const float top = params.sun_elevation + half;
    m.sun_bottom_ = sun_radiance(bottom > 0.0f ? bottom : 0.0f, altitude, params.air_density,
                                 params.dust_density, solid_angle);
    m.sun_top_ = sun_radiance(top > 0.0f ? top : 0.0f, altitude, params.air_density,
                              params.dust_density, solid_angle);
    float rotation = std::fmod(params.sun_rotation, kTwoPi);
    if (rotation < 0.0f) {
        rotation += kTwoPi;
    }
    m.sun_rotation_ = kTwoPi - rotation;
    m.sun_elevation_ = params.sun_elevation;
    m.sun_diameter_ = params.sun_disc ? diameter : -1.0f;
    m.sun_intensity_ = params.sun_intensity;
    const Atmosphere atm{{params.air_density, params.dust_density, params.ozone_density}};
    m.table_ = std::make_shared<const std::vector<float3>>(
        nishita_table(params.sun_elevation, altitude, atm));
    return m;
}

// ---- Evaluation (Cycles' SVM kernel) ---------------------------------------------------------

float3 SkyModel::radiance(float3 dir) const {
    switch (type_) {
        case SkyType::PREETHAM:
            return preetham(dir);
        case SkyType::HOSEK_WILKIE:
            return hosek_wilkie(dir);
        case SkyType::NISHITA:
            break;
    }
    return nishita(dir);
}

float3 SkyModel::table_texel(int x, int y) const {
    if (!table_) {
        return float3(0.0f);
    }
    x = std::clamp(x, 0, kTableWidth - 1);
    y = std::clamp(y, 0, kTableHeight - 1);
    return (*table_)[static_cast<size_t>(y) * kTableWidth + x];
}

float3 SkyModel::preetham(float3 dir) const {
    const Spherical s = to_spherical(dir);
    const float gamma = spherical_angle(s.theta, s.phi, sun_theta_, sun_phi_);
    const float theta = std::min(s.theta, kHalfPi - 0.001f);
    const float x = scale_[1] * perez(config_[1], theta, gamma);
    const float y = scale_[2] * perez(config_[2], theta, gamma);
    const float lum = scale_[0] * perez(config_[0], theta, gamma);
    // xyY -> XYZ (Cycles' xyY_to_xyz, zero where y is zero).
    const float big_x = y != 0.0f ? (x / y) * lum : 0.0f;
    const float big_z = (y != 0.0f && lum != 0.0f) ? (1.0f - x - y) / y * lum : 0.0f;
    return xyz_to_scene_linear({big_x, lum, big_z});
}

float3 SkyModel::hosek_wilkie(float3 dir) const {
    const Spherical s = to_spherical(dir);
    const float gamma = spherical_angle(s.theta, s.phi, sun_theta_, sun_phi_);
    const float theta = std::min(s.theta, kHalfPi - 0.001f);
    const float3 xyz(hosek_distribution(config_[0], theta, gamma) * scale_[0],
                     hosek_distribution(config_[1], theta, gamma) * scale_[1],
                     hosek_distribution(config_[2], theta, gamma) * scale_[2]);
    return xyz_to_scene_linear(xyz) * (kTwoPi / 683.0f);
}

// Cycles' bilinear image lookup (INTERPOLATION_LINEAR, EXTENSION_EXTEND) of the table at
// normalized (x, y).
float3 SkyModel::table_lookup(float x, float y) const {
    // Integer part (rounded down) and fraction, as Cycles' frac(). Coordinates are first
    // limited to just beyond the table, which changes no result (the texel indices are clamped
    // to the edge anyway) but keeps the conversion defined for any input, NaN included.
    const auto split = [](float v, int size, int* i) {
        v = std::fmin(std::fmax(v, -2.0f), static_cast<float>(size + 1));
        *i = static_cast<int>(v) - (v < 0.0f ? 1 : 0);
        return v - static_cast<float>(*i);
    };
    int ix, iy;
    const float tx = split(x * static_cast<float>(kTableWidth) - 0.5f, kTableWidth, &ix);
    const float ty = split(y * static_cast<float>(kTableHeight) - 0.5f, kTableHeight, &iy);
    const int x0 = std::clamp(ix, 0, kTableWidth - 1);
    const int x1 = std::clamp(ix + 1, 0, kTableWidth - 1);
    const int y0 = std::clamp(iy, 0, kTableHeight - 1);
    const int y1 = std::clamp(iy + 1, 0, kTableHeight - 1);
    const std::vector<float3>& t = *table_;
    const auto at = [&](int px, int py) { return t[static_cast<size_t>(py) * kTableWidth + px]; };
    return (1.0f - ty) * (1.0f - tx) * at(x0, y0) + (1.0f - ty) * tx * at(x1, y0) +
           ty * (1.0f - tx) * at(x0, y1) + ty * tx * at(x1, y1);
}

float3 SkyModel::nishita(float3 dir) const {
    const Spherical s = to_spherical(dir);
    // Table column: longitude relative to the sun, wrapped once into [0, 1].
    float u = (s.phi + kPi + sun_rotation_) / kTwoPi;
    if (u > 1.0f) {
        u -= 1.0f;
    }
    float3 xyz(0.0f);
    if (dir.z >= 0.0f) {
        const float3 sun_dir = geographic_direction(sun_elevation_, sun_rotation_ + kHalfPi);
        const float sun_angle = angle_between(dir, sun_dir);
        const float half = sun_diameter_ / 2.0f;
        const float elevation = kHalfPi - s.theta;
        if (sun_diameter_ >= 0.0f && sun_angle < half) {
            // Inside the disc: interpolate the sun's radiance by elevation across the disc
            // (over its visible part when the disc crosses the horizon).
            if (sun_elevation_ - half > 0.0f) {
                const float t = (elevation - sun_elevation_) / sun_diameter_ + 0.5f;
                xyz = lerp(sun_bottom_, sun_top_, t) * sun_intensity_;
            } else if (sun_elevation_ + half > 0.0f) {
                const float t = elevation / (sun_elevation_ + half);
                xyz = lerp(sun_bottom_, sun_top_, t) * sun_intensity_;
            }
            const float limb = 1.0f - 0.6f * (1.0f - std::sqrt(1.0f - sqr(sun_angle / half)));
            xyz *= limb;
        } else {
            // Rows sit at elevations growing with the square of the row: undo that.
            const float v = std::sqrt(std::max(elevation / kHalfPi, 0.0f));
            xyz = table_lookup(u, v);
        }
    } else if (dir.z >= -0.4f) {
        // Below the horizon: the horizon row, fading to black at z = -0.4.
        float fade = 1.0f + dir.z * 2.5f;
        fade = sqr(fade) * fade;
        xyz = table_lookup(u, -0.5f) * fade;
    }
    return xyz_to_scene_linear(xyz);
}

}  // namespace glint::render::shader
