// The path tracer's media (path.h): the volume stack, the media acting on a segment, and
// carrying paths and shadow rays through them.
#include <algorithm>
#include <cmath>

#include "render/integrators/path.h"

namespace glint::render {
namespace {

// Collisions on one segment before the tracking gives up (a bound against runaway loops).
constexpr int kMaxCollisions = 1 << 20;

// A uniform number in [0, 1) from a 32-bit hash stream (ratio tracking of shadow rays).
double hash_uniform(uint32_t* seed) {
    *seed = hash_u32(*seed + 0x9e3779b9U);
    return static_cast<double>(*seed) * (1.0 / 4294967296.0);
}

bool finite(const Color& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}
double average(const Color& c) { return (c.r + c.g + c.b) / 3; }
double channel(const Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }

}  // namespace

void PathIntegrator::MediumStack::cross(const Hit& hit, const Vec3& dir,
                                        const PathIntegrator& pi) {
    if (hit.object < 0) return;
    if (dot(dir, hit.ng) < 0) {
        // Entering (the geometric normal points out of the solid).
        if (count == kMax) return;  // deeper nesting than any sane scene: ignore it
        object[count] = hit.object;
        medium[count] = hit.material >= 0 ? pi.material_medium_[static_cast<size_t>(hit.material)]
                                          : -1;
        // Blender's objects (node-graph materials) hold their volumes whatever encloses them.
        hollow[count] = pi.scene_.objects[static_cast<size_t>(hit.object)].hollow ||
                        (hit.material >= 0 &&
                         pi.scene_.materials[static_cast<size_t>(hit.material)].graph >= 0);
        ++count;
        return;
    }
    for (int i = count - 1; i >= 0; --i) {
        if (object[i] != hit.object) continue;
        for (int j = i; j + 1 < count; ++j) {
            object[j] = object[j + 1];
            medium[j] = medium[j + 1];
            hollow[j] = hollow[j + 1];
        }
        --count;
        return;
    }
}

int PathIntegrator::active_media(const MediumStack& stack, const PathMedium** out) const {
    // As in POV-Ray's classic renderer: media act only while every object the ray is inside
    // is hollow (Ray::IsHollowRay); the atmosphere's then too.
    for (int i = 0; i < stack.count; ++i)
        if (!stack.hollow[i]) return 0;
    int n = 0;
    for (int i = 0; i < stack.count; ++i)
        if (stack.medium[i] >= 0) out[n++] = &media_[static_cast<size_t>(stack.medium[i])];
    if (world_medium_ >= 0) out[n++] = &media_[static_cast<size_t>(world_medium_)];
    return n;
}

void PathIntegrator::medium_at(const PathMedium* const* media, int n, const Vec3& p,
                               MediumPoint* out) const {
    if (n == 1) {
        media[0]->at(p, out);
        return;
    }
    *out = MediumPoint{};
    for (int k = 0; k < n; ++k) {
        MediumPoint m;
        media[k]->at(p, &m);
        out->sigma_a += m.sigma_a;
        out->emission += m.emission;
        for (int i = 0; i < m.lobe_count; ++i) {
            if (out->lobe_count < MediumPoint::kMaxLobes)
                out->lobes[out->lobe_count++] = m.lobes[i];
            else  // more lobes than room: the scattering still counts, in the last shape
                out->lobes[MediumPoint::kMaxLobes - 1].sigma_s += m.lobes[i].sigma_s;
        }
    }
}

Color PathIntegrator::media_transmittance(const PathMedium* const* media, int n,
                                          const Vec3& origin, const Vec3& dir, double dist,
                                          uint32_t* seed) const {
    bool homogeneous = true;
    double majorant = 0;
    for (int k = 0; k < n; ++k) {
        homogeneous = homogeneous && media[k]->homogeneous();
        majorant += media[k]->majorant();
    }
    if (!(majorant > 0)) return Color(1, 1, 1);
    MediumPoint m;
    if (homogeneous) {
        medium_at(media, n, origin, &m);
        const Color st = m.sigma_t();
        auto tr = [dist](double s) { return s > 0 ? std::exp(-s * dist) : 1.0; };
        return Color(tr(st.r), tr(st.g), tr(st.b));
    }
    // Ratio tracking (Novak et al. 2014): the product of the null-collision probabilities at
    // tentative collisions drawn against the majorant; Russian roulette once it is small.
    Color t(1, 1, 1);
    double x = 0;
    for (int i = 0; i < kMaxCollisions; ++i) {
        x -= std::log(1 - hash_uniform(seed)) / majorant;
        if (!(x < dist)) return t;
        medium_at(media, n, origin + dir * x, &m);
        const Color st = m.sigma_t();
        t *= Color(std::max(0.0, 1 - st.r / majorant), std::max(0.0, 1 - st.g / majorant),
                   std::max(0.0, 1 - st.b / majorant));
        const double mx = t.max();
        if (!(mx > 0)) return Color();
        if (mx < 0.1) {
            if (hash_uniform(seed) >= mx) return Color();
            t *= 1 / mx;
        }
    }
    return t;
}

int PathIntegrator::track(const PathMedium* const* act, int na, const Ray& r, double tmax,
                          VolumeRandom& random, Color* beta, Color* emitted, double* t_out,
                          MediumPoint* mp) const {
    bool homogeneous = true, emissive = false;
    double mu = 0;
    for (int k = 0; k < na; ++k) {
        homogeneous = homogeneous && act[k]->homogeneous();
        emissive = emissive || act[k]->emissive();
        mu += act[k]->majorant();
    }
    if (homogeneous) {
        // Closed forms: the emission integrated over the segment, and a distance drawn
        // exponentially in one channel, picked by throughput times albedo, with the pdf of
        // all the channels' choices together (one-sample spectral MIS, as Cycles does).
        medium_at(act, na, r.origin, mp);
        const Color st = mp->sigma_t(), ss = mp->sigma_s();
        auto transmit = [&](double d) {
            auto one = [d](double s) { return s > 0 ? std::exp(-s * d) : 1.0; };
            return Color(one(st.r), one(st.g), one(st.b));
        };
        if (emissive && !mp->emission.is_black()) {
            auto integral = [tmax](double s) {
                if (!(s > 0)) return tmax;  // (infinite for an endless segment: dropped below)
                return std::isinf(tmax) ? 1 / s : -std::expm1(-s * tmax) / s;
            };
            const Color e = *beta * mp->emission *
                            Color(integral(st.r), integral(st.g), integral(st.b));
            if (finite(e)) *emitted += e;
        }
        if (ss.is_black()) {
            *beta *= transmit(tmax);
            return beta->is_black() ? 2 : 0;
        }
        double w[3];
        double total = 0;
        for (int c = 0; c < 3; ++c) {
            const double sc = channel(st, c);
            w[c] = std::fabs(channel(*beta, c)) * (sc > 0 ? channel(ss, c) / sc : 0);
            total += w[c];
        }
        for (int c = 0; c < 3; ++c) w[c] = total > 0 ? w[c] / total : 1.0 / 3;
        const double u = random();
        const int c = u < w[0] ? 0 : u < w[0] + w[1] ? 1 : 2;
        const double sc = channel(st, c);
        const double t = sc > 0 ? -std::log(1 - random()) / sc : kInfinity;
        if (t < tmax) {
            const Color tr = transmit(t);
            double pdf = 0;
            for (int k = 0; k < 3; ++k) pdf += w[k] * channel(st, k) * channel(tr, k);
            if (!(pdf > 0)) return 2;
            *beta *= ss * tr * (1 / pdf);
            *t_out = t;
            return 1;
        }
        const Color tr = transmit(tmax);
        double p = 0;
        for (int k = 0; k < 3; ++k) p += w[k] * channel(tr, k);
        if (!(p > 0)) return 2;
        *beta *= tr * (1 / p);
        return 0;
    }
    // Null-collision (delta) tracking against the summed majorants, weighted per channel:
    // each tentative collision adds the media's emission (the collision estimator), then
    // absorbs, scatters or passes with probabilities from the channel-averaged coefficients,
    // the weights correcting each channel.
    // Emission alone has no extinction to draw collisions by: some every few units of the
    // segment still integrate it.
    if (emissive && !std::isinf(tmax)) mu = std::max(mu, 8.0 / std::max(tmax, 1e-12));
    if (!(mu > 0)) return 0;
    double t = 0;
    for (int i = 0; i < kMaxCollisions; ++i) {
        t -= std::log(1 - random()) / mu;
        if (!(t < tmax)) return 0;
        medium_at(act, na, r.origin + r.dir * t, mp);
        if (!mp->emission.is_black()) *emitted += *beta * mp->emission * (1 / mu);
        const Color ss = mp->sigma_s(), sa = mp->sigma_a;
        const Color sn(std::max(0.0, mu - sa.r - ss.r), std::max(0.0, mu - sa.g - ss.g),
                       std::max(0.0, mu - sa.b - ss.b));
        const double pa = average(sa) / mu, ps = average(ss) / mu, pn = average(sn) / mu;
        const double xi = random() * (pa + ps + pn);
        if (xi < pa) return 2;
        if (xi < pa + ps) {
            *beta *= ss * (1 / (mu * ps));
            *t_out = t;
            return 1;
        }
        *beta *= sn * (1 / (mu * pn));
        if (beta->is_black() || !finite(*beta)) return 2;
    }
    return 2;
}

}  // namespace glint::render
