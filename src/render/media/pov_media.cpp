#include "render/media/pov_media.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/special.h"

namespace glint::render {
namespace {

constexpr double kMaxDistance = 1.0e7;      // POV-Ray's MAX_DISTANCE
constexpr double kSmallTolerance = 1.0e-3;  // POV-Ray's SMALL_TOLERANCE

Color exp_neg(const Color& c) { return Color(std::exp(-c.r), std::exp(-c.g), std::exp(-c.b)); }
double greyscale(const Color& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }
double colour_distance(const Color& a, const Color& b) {
    return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

// Where a ray crosses a cone or cylinder about a light's axis (a t^2 + 2 b t + c = 0 with a
// positive discriminant d): the two distances, sorted, and the heights along the axis there
// (k1, k2: the ray's direction and origin along the axis).
struct Crossings {
    double x1, x2, l1, l2;
};
Crossings crossings(double a, double b, double d, double k1, double k2) {
    d = std::sqrt(d);
    double x1 = (-b + d) / a, x2 = (-b - d) / a;
    if (x1 > x2) std::swap(x1, x2);
    return {x1, x2, k2 + x1 * k1, k2 + x2 * k1};
}

uint64_t mix(uint64_t h, double v) {
    h ^= std::bit_cast<uint64_t>(v) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    return h;
}

}  // namespace

// POV-Ray draws jitter and method 1's sample positions from the thread's random stream, so
// its images depend on render order; glint seeds a stream from the ray, so they depend on
// nothing else (same distribution, other numbers). Method 2 and 3 without jitter use none.
struct PovMedia::Context {
    const std::vector<const scene::Media*>& media;
    Vec3 origin, dir;
    double depth;
    bool shadow;
    const LightFn& light;
    bool use_scattering = false;
    bool collects = false;            // some medium takes photons (not `collect off`)
    double jitter = 0.0;              // the lead medium's
    double aa_threshold = HUGE_VAL;   // the smallest of all media
    std::vector<SegmentLight> lights;
    uint64_t state;

    double random() {
        state += 0x9E3779B97F4A7C15ull;
        uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
    }
};

PovMedia::PovMedia(const scene::Scene& scene, const std::vector<scene::Light>& lights,
                   const PigmentEvaluator* pigments)
    : pigments_(pigments) {
    for (const scene::Light& l : lights) {
        Geometry g;
        g.kind = l.kind;
        g.center = l.location;
        Vec3 d = l.point_at - l.location;
        double len = length(d);
        g.direction = len > kPovEpsilon ? d / len : d;
        g.falloff = l.kind == scene::LightKind::Spot ? std::cos(l.falloff * kPi / 180.0)
                                                       : l.falloff;
        // shadowless lights are POV-Ray's fill lights, which media never see.
        g.interacts = l.media_interaction && !l.shadowless && !l.blender;
        lights_.push_back(g);
    }
    auto prepare = [&](const scene::Media& m) {
        if (m.method != 3 && m.max_samples > m.min_samples)
            thresholds_.emplace(&m, sample_thresholds(m));
    };
    for (const scene::Media& m : scene.media) prepare(m);
    for (const scene::Material& mat : scene.materials)
        for (const scene::Media& m : mat.interior.media) prepare(m);
}

double PovMedia::chi_square_upper_inverse(double df, double y) {
    // Q(df / 2, x / 2) falls from 1 to 0 as x grows: bisect for y.
    if (!(y > 0.0 && y < 1.0) || !(df > 0.0)) return 0.0;
    double lo = 0.0, hi = std::max(1.0, df);
    while (regularized_gamma_q(0.5 * df, 0.5 * hi) > y && hi < 1e8) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
        double mid = 0.5 * (lo + hi);
        if (regularized_gamma_q(0.5 * df, 0.5 * mid) > y) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

std::vector<double> PovMedia::sample_thresholds(const scene::Media& m) {
    std::vector<double> out(std::max(1, m.max_samples), 0.0);
    if (m.max_samples > 1) {
        double t = chi_square_upper_inverse(m.max_samples - 1, m.confidence);
        t = t > 0.0 ? m.variance / t : m.variance * kPovEpsilon;
        for (int i = 0; i < m.max_samples; ++i)
            out[i] = t * chi_square_upper_inverse(i + 1, m.confidence);
    }
    return out;
}

void PovMedia::compute(const std::vector<const scene::Media*>& media, const Vec3& origin,
                       const Vec3& dir, double depth, bool shadow, const LightFn& light,
                       Color* colour, double* transm) const {
    if (media.empty()) return;
    Context c{media, origin, dir, depth, shadow, light, false, false, 0.0, HUGE_VAL, {}, 0};
    c.state = mix(mix(mix(mix(mix(mix(0x243F6A8885A308D3ull, origin.x), origin.y), origin.z),
                          dir.x), dir.y), dir.z);

    // The medium with the most intervals sets the sampling; the smallest aa_threshold wins.
    const scene::Media* lead = media.front();
    bool use_extinction = false;
    // POV-Ray 3.7 keeps densities in a list, last parsed first, and looks at that one only.
    bool constant_shadow = shadow;
    for (const scene::Media* m : media) {
        if (m->intervals > lead->intervals) lead = m;
        c.aa_threshold = std::min(c.aa_threshold, m->aa_threshold);
        use_extinction = use_extinction || !m->absorption.is_black() || !m->scattering.is_black();
        c.use_scattering = c.use_scattering || !m->scattering.is_black();
        c.collects = c.collects || m->collect;
        if (!m->density.empty())
            constant_shadow =
                constant_shadow && m->density.back().kind == scene::PatternKind::Plain;
    }
    if (shadow && !use_extinction) return;
    c.jitter = lead->jitter;

    // Lit parts of the segment, then the intervals to sample.
    struct Lit {
        bool lit;
        double s0, s1;
    };
    std::vector<Lit> lit;
    if (!shadow) {
        light_intervals(c, &c.lights);
        if (!c.lights.empty()) {
            std::vector<double> s0, s1;
            for (const SegmentLight& l : c.lights) {
                s0.push_back(l.s0);
                s1.push_back(l.s1);
            }
            std::sort(s0.begin(), s0.end());
            std::sort(s1.begin(), s1.end());
            if (s0[0] > 0.0) lit.push_back({false, 0.0, s0[0]});
            lit.push_back({true, s0[0], s1[0]});
            for (size_t i = 1; i < s0.size(); ++i) {
                if (s0[i] > lit.back().s1) {
                    lit.push_back({false, lit.back().s1, s0[i]});
                    lit.push_back({true, s0[i], s1[i]});
                } else if (s1[i] > lit.back().s1) {
                    lit.back().s1 = s1[i];
                }
            }
            if (lit.back().s1 < depth) lit.push_back({false, lit.back().s1, depth});
        }
    }
    if (lit.empty()) lit.push_back({false, 0.0, depth});

    std::vector<Interval> iv;
    auto add = [&](bool l, double s0, double s1, double ds) {
        Interval i;
        i.lit = l;
        i.s0 = s0;
        i.s1 = s1;
        i.ds = ds;
        iv.push_back(i);
    };
    const size_t intervals = std::max(static_cast<size_t>(lead->intervals), lit.size());
    if (lit.size() == 1) {
        const double ds = lit[0].s1 - lit[0].s0;
        if (!lit[0].lit && lead->density.empty()) {
            add(false, lit[0].s0, lit[0].s1, ds);
        } else {
            const double delta = ds / static_cast<double>(intervals);
            for (size_t i = 0; i < intervals; ++i)
                add(lit[0].lit, lit[0].s0 + delta * i, lit[0].s0 + delta * (i + 1), delta);
        }
    } else {
        // More intervals where lights shine: `ratio` of them, shared by the lit parts.
        double sum = 0.0;
        for (const Lit& l : lit) sum += l.lit ? lead->ratio : 1.0 - lead->ratio;
        size_t remaining = intervals;
        for (size_t i = 0; i < lit.size(); ++i) {
            const double weight = lit[i].lit ? lead->ratio : 1.0 - lead->ratio;
            size_t n = static_cast<size_t>(weight / sum * static_cast<double>(intervals)) + 1;
            const size_t r = remaining - lit.size() + i + 1;
            if (n > r) n = r;
            const double delta = (lit[i].s1 - lit[i].s0) / static_cast<double>(n);
            for (size_t j = 0; j < n; ++j)
                add(lit[i].lit, lit[i].s0 + delta * j, lit[i].s0 + delta * (j + 1), delta);
            remaining -= n;
        }
    }
    if (iv.front().s0 > 0.0) {
        Interval i;
        i.s1 = i.ds = iv.front().s0;
        iv.insert(iv.begin(), i);
    }
    if (iv.back().s1 < depth) add(false, iv.back().s1, depth, depth - iv.back().s1);

    const int min_samples = lead->min_samples;
    Color col, od;
    if (lead->method == 3 && !constant_shadow) {
        // ComputeMediaAdaptiveSampling (3.7): sub-intervals between evenly spaced samples,
        // each refined recursively where neighbouring samples differ by more than
        // aa_threshold. The samples span the first count/(count+1) of the interval only.
        for (Interval& i : iv) {
            const int count = std::max(2, static_cast<int>(min_samples / 2.0) + 1);
            const double dd = 1.0 / static_cast<double>(count + 1);
            double d0 = 0.0;
            Color c0, od0, c1, od1, result, od_result;
            sample(c, i, d0 + dd * lead->jitter * (c.random() - 0.5), 3, &c0, &od0);
            i.te = Color();
            i.od = Color();
            d0 += dd;
            for (int j = 1; j <= count; ++j, d0 += dd) {
                sample(c, i, d0 + dd * lead->jitter * (c.random() - 0.5), 3, &c1, &od1);
                sample_recursive(c, i, d0 - dd, d0, c0, c1, od0, od1, lead->aa_level - 1,
                                 &result, &od_result);
                // Attenuated by the sub-intervals before it, as the samples come in order.
                i.te += result * exp_neg(i.od * (1.0 / count));
                c0 = c1;
                i.od += od_result;
                od0 = od1;
            }
            i.samples = count;
        }
    } else {
        // ComputeMediaRegularSampling: min_samples per interval, random (method 1) or
        // stratified (method 2), then more (random) while the estimate's variance is above
        // the confidence threshold, up to max_samples.
        for (Interval& i : iv) {
            for (int j = 0; j < min_samples; ++j) {
                if (lead->method == 2) {
                    double d0 = (j + 0.5) / min_samples + c.random() * lead->jitter / min_samples;
                    sample(c, i, d0, 2, &col, &od);
                } else {
                    sample(c, i, c.random(), 1, &col, &od);
                }
                if (constant_shadow) break;
            }
        }
        auto th = thresholds_.find(lead);
        if (!shadow && lead->max_samples > min_samples && th != thresholds_.end()) {
            for (Interval& i : iv) {
                if (i.samples >= lead->max_samples) continue;
                auto variance = [&] {
                    const double n = 1.0 / i.samples;
                    return (i.te2 * n - (i.te * n) * (i.te * n)) * n;
                };
                for (Color va = variance();;) {
                    const double t = th->second[i.samples - 1];
                    if (std::fabs(va.r) < t && std::fabs(va.g) < t && std::fabs(va.b) < t) break;
                    sample(c, i, c.random(), 1, &col, &od);
                    if (i.samples > lead->max_samples) break;
                    va = variance();
                }
            }
        }
    }

    // ComputeMediaColour: each interval's emission is dimmed by the optical depth before it.
    Color total_od, te;
    for (const Interval& i : iv) {
        const double n = 1.0 / i.samples;
        te += i.te * n * exp_neg(total_od);
        total_od += i.od * n;
    }
    const Color t = exp_neg(total_od);
    *colour = *colour * t + te;
    if (transm) *transm *= greyscale(t);
}

void PovMedia::light_intervals(const Context& c, std::vector<SegmentLight>* out) const {
    // ComputeOneMediaLightInterval: the part of the segment each light can reach.
    for (size_t li = 0; li < lights_.size(); ++li) {
        const Geometry& g = lights_[li];
        if (!g.interacts) continue;
        double t1 = 0.0, t2 = 0.0;
        bool insert = false;
        const Vec3 v1 = c.origin - g.center;
        const double k1 = dot(c.dir, g.direction);
        const double k2 = dot(v1, g.direction);
        if (g.kind == scene::LightKind::Point) {
            t1 = 0.0;
            t2 = c.depth;
            insert = true;
        } else if (g.kind == scene::LightKind::Spot) {
            // ComputeSpotLightInterval: where the ray crosses the falloff cone.
            const double m = 1.0 / (g.falloff * g.falloff);
            const double l = length(v1);
            const bool in_cone = l > kPovEpsilon && k2 / l >= g.falloff;
            if (k1 <= 0.0 && k2 < 0.0) continue;
            const double k3 = dot(v1, c.dir), k4 = dot(v1, v1);
            const double a = 1.0 - k1 * k1 * m, b = k3 - k1 * k2 * m, cc = k4 - k2 * k2 * m;
            bool found = false;
            if (a != 0.0) {
                const double d = b * b - a * cc;
                if (d > kPovEpsilon) {
                    auto [x1, x2, l1, l2] = crossings(a, b, d, k1, k2);
                    if (l1 <= 0.0 && l2 <= 0.0) continue;
                    if (l1 <= 0.0 || l2 <= 0.0) {
                        if (l1 <= 0.0) {
                            if (in_cone) {
                                x1 = 0.0;
                                x2 = x2 > 0.0 ? x2 : kMaxDistance;
                            } else {
                                x1 = x2;
                                x2 = kMaxDistance;
                            }
                        } else if (in_cone) {
                            x2 = x1;
                            x1 = 0.0;
                        } else {
                            x2 = kMaxDistance;
                        }
                    }
                    t1 = x1;
                    t2 = x2;
                    found = true;
                } else if (d > -kPovEpsilon) {
                    if (in_cone) {
                        t1 = 0.0;
                        t2 = -b / a;
                    } else {
                        t1 = -b / a;
                        t2 = kMaxDistance;
                    }
                    found = true;
                }
            } else if (in_cone) {
                t1 = 0.0;
                t2 = -cc / b;
                found = true;
            }
            insert = found && t1 < c.depth && t2 > kSmallTolerance;
        } else {
            // ComputeCylinderLightInterval: where the ray crosses the beam's cylinder.
            if (k1 <= 0.0 && k2 < 0.0) continue;
            const double a = 1.0 - k1 * k1;
            if (a == 0.0) continue;
            const double k3 = dot(v1, c.dir), k4 = dot(v1, v1);
            const double b = k3 - k1 * k2, cc = k4 - k2 * k2 - g.falloff * g.falloff;
            const double d = b * b - a * cc;
            if (!(d > kPovEpsilon)) continue;
            auto [x1, x2, l1, l2] = crossings(a, b, d, k1, k2);
            if (l1 <= 0.0 && l2 <= 0.0) continue;
            if (l1 <= 0.0 || l2 <= 0.0) {
                if (l1 <= 0.0) x1 = 0.0;
                else x2 = (kMaxDistance - k2) / k1;
            }
            t1 = x1;
            t2 = x2;
            insert = t1 < c.depth && t2 > kSmallTolerance;
        }
        if (insert) out->push_back({li, std::max(t1, 0.0), std::min(t2, c.depth)});
    }
}

double PovMedia::phase(const std::vector<const scene::Media*>& media, const Vec3& to_light,
                       const Vec3& dir) {
    // ComputeMediaScatteringAttenuation: the phase functions of all media, averaged.
    const double alpha = dot(to_light, dir);
    double k = 0.0;
    for (const scene::Media* m : media) {
        switch (m->type) {
            case scene::ScatteringType::Rayleigh: k += 0.799372013 * (1.0 + alpha * alpha); break;
            case scene::ScatteringType::MieHazy:
                k += 0.576655375 * (1.0 + 9.0 * std::pow(0.5 * (1.0 + alpha), 8.0));
                break;
            case scene::ScatteringType::MieMurky:
                k += 0.495714547 * (1.0 + 50.0 * std::pow(0.5 * (1.0 + alpha), 32.0));
                break;
            case scene::ScatteringType::HenyeyGreenstein: {
                const double g = m->eccentricity;
                k += (1.0 - g * g) / std::pow(1.0 + g * g - 2.0 * g * alpha, 1.5);
                break;
            }
            case scene::ScatteringType::Isotropic: k += 1.0; break;
        }
    }
    return k / static_cast<double>(media.size());
}

void PovMedia::sample(Context& c, Interval& iv, double d0, int method, Color* col,
                      Color* od) const {
    // ComputeOneMediaSample: coefficients at the sample, light scattered there.
    d0 *= iv.ds;
    const double d1 = iv.s0 + d0;
    const Vec3 h = c.origin + c.dir * d1;
    Color extinction, emission, scattering;
    for (const scene::Media* m : c.media) {
        // Evaluate_Density_Pigment: the densities multiply; none is 1.
        Color density(1.0);
        for (const scene::Pigment& d : m->density) {
            scene::ColorFT pc;
            if (pigments_->evaluate(d, PatternPoint{h, Vec2{0, 0}, false}, &pc))
                density *= pc.rgb;
            else
                density = Color();
        }
        extinction += density * (m->absorption + m->scattering * m->extinction);
        if (!c.shadow) {
            emission += density * m->emission;
            scattering += density * m->scattering;
        }
    }
    *od = extinction * iv.ds;
    if (method != 3) iv.od += *od;

    if (!c.shadow && c.use_scattering && iv.lit) {
        for (const SegmentLight& sl : c.lights) {
            if (d1 < sl.s0 || d1 > sl.s1) continue;
            Color lc;
            Vec3 ldir;
            if (!c.light(sl.light, h, &lc, &ldir)) continue;
            emission += scattering * lc * phase(c.media, ldir, c.dir);
        }
    }
    if (!c.shadow && c.use_scattering && photons_ && photons_->size() > 0 && c.collects) {
        // ComputeMediaPhotons: each photon near the sample scatters like a light from where
        // it came, over the sphere it was gathered from.
        PhotonGather g;
        photons_->gather(h, nullptr, &g);
        if (g.radius > 0) {
            Color sum;
            for (const Photon* ph : g.photons)
                sum += scattering * ph->power * phase(c.media, ph->to_source, c.dir);
            emission += sum * (3.0 / (4.0 * kPi * g.radius * g.radius * g.radius));
        }
    }
    if (method == 3) {
        // Attenuated later, in order (the adaptive sampler).
        emission *= iv.ds;
    } else {
        // Assumes constant extinction over the interval.
        emission *= exp_neg(extinction * d0) * iv.ds;
    }
    *col = emission;
    if (method != 3) {
        iv.te += emission;
        iv.te2 += emission * emission;
    }
    ++iv.samples;
}

void PovMedia::sample_recursive(Context& c, Interval& iv, double d1, double d3, const Color& c1,
                                const Color& c3, const Color& od1, const Color& od3, int depth,
                                Color* result, Color* od_result) const {
    // ComputeOneMediaSampleRecursive, with POV-Ray's weights (1:1:1 at the deepest level,
    // 2:1 / 1:2 halves elsewhere).
    const double d2 = 0.5 * (d1 + d3);
    const double jdist = d2 + c.jitter * (d3 - d1) * (c.random() - 0.5);
    Color c2, od2;
    sample(c, iv, jdist, 3, &c2, &od2);
    if (depth <= 0) {
        *result = (c1 + c2 + c3) / 3.0;
        *od_result = (od1 + od2 + od3) / 3.0;
        return;
    }
    Color r2, o2;
    if (colour_distance(c1, c2) > c.aa_threshold) {
        sample_recursive(c, iv, d1, d2, c1, c2, od1, od2, depth - 1, &r2, &o2);
        *result = r2 / 2.0;
        *od_result = o2 / 2.0;
    } else {
        *result = c1 / 3.0 + c2 / 6.0;
        *od_result = od1 / 3.0 + od2 / 6.0;
    }
    if (colour_distance(c2, c3) > c.aa_threshold) {
        sample_recursive(c, iv, d2, d3, c2, c3, od2, od3, depth - 1, &r2, &o2);
        *result += r2 / 2.0;
        *od_result += o2 / 2.0;
    } else {
        *result += c2 / 6.0 + c3 / 3.0;
        *od_result += od2 / 6.0 + od3 / 3.0;
    }
}

}  // namespace glint::render
