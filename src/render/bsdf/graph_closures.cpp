#include "render/bsdf/graph_closures.h"

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

double average(const Color& c) { return (c.r + c.g + c.b) / 3; }

}  // namespace

void add_graph_closure(ClosureSet& set, const shader::Closure& c, const Vec3& n,
                       double outside, double shade, bool diffuse_ancestor) {
    using shader::ClosureKind;
    using shader::Distribution;
    const Color w = c.weight * shade;
    const Color wc = w * c.color;
    const double share = c.sample_weight * shade;
    const Vec3* tangent = length_squared(c.T) > 0 ? &c.T : nullptr;
    const Microfacet::Kind mf = c.distribution == Distribution::Beckmann
                                    ? Microfacet::Kind::Beckmann : Microfacet::Kind::GGX;
    const double alpha = c.roughness * c.roughness;
    switch (c.kind) {
        case ClosureKind::Diffuse:
            if (c.roughness > 0) set.add(Lobe::oren_nayar(c.roughness), wc, n, share);
            else set.add(Bsdf::lambert(c.color), w, n, share);
            return;
        case ClosureKind::Translucent: set.add(Lobe::translucent(), wc, n, share); return;
        case ClosureKind::Toon:
            set.add(Lobe::toon(c.glossy, c.roughness, c.smooth), wc, n, share);
            return;
        case ClosureKind::Velvet: set.add(Lobe::velvet(c.roughness), wc, n, share); return;
        case ClosureKind::Glossy: {
            // Cycles' Anisotropic BSDF: alpha shrinks along one axis and grows along the other.
            const double an = std::clamp(c.anisotropy, -0.99, 0.99);
            double ax = alpha, ay = alpha;
            if (tangent && an < 0) {
                ax = alpha / (1 + an);
                ay = alpha * (1 + an);
            } else if (tangent) {
                ax = alpha * (1 - an);
                ay = alpha / (1 - an);
            }
            if (c.distribution == Distribution::AshikhminShirley)
                set.add(Lobe::ashikhmin_shirley(ax, ay), wc, n, share, tangent);
            else if (c.distribution == Distribution::MultiGGX)
                set.add(Lobe::multi_ggx(MultiGgx{ax, ay, false, c.color}), wc, n, share, tangent);
            else
                set.add(Lobe::reflection(Microfacet{mf, ax, ay}), wc, n, share, tangent);
            return;
        }
        case ClosureKind::Refraction:
            set.add(Lobe::refraction(Microfacet{mf, alpha, alpha}, c.ior), wc, n, share);
            return;
        case ClosureKind::Glass: {
            if (c.distribution == Distribution::MultiGGX) {
                // Cycles' Multiscatter GGX glass: the colour weighs the first scattering and
                // tints each one after it.
                set.add(Lobe::multi_glass(MultiGlass{alpha, c.ior, c.color}), wc, n, share);
                return;
            }
            PrincipledParams p;
            p.base = Color(1, 1, 1);
            p.roughness = c.roughness;
            p.transmission = 1;
            p.ior = c.ior;
            p.glass_distribution = mf;
            set.add(Bsdf::principled(p), wc, n, share);
            return;
        }
        case ClosureKind::Subsurface: {
            // Cycles' Subsurface Scattering node: the BSSRDF of the colour; after a diffuse
            // bounce (or for channels of too small a radius) plain diffuse.
            Bssrdf b;
            b.weight = wc;
            b.radius = diffuse_ancestor ? Color() : c.subsurface_radius * c.subsurface;
            b.albedo = c.color;
            b.anisotropy = std::clamp(c.subsurface_anisotropy, 0.0, 0.9);
            b.n = n;
            if (!(std::fabs(average(wc)) >= 1e-5)) return;
            Color diffuse;
            b.setup(c.subsurface_method != shader::SubsurfaceMethod::RandomWalk,
                    std::clamp(c.subsurface_ior, 1.01, 3.8), &diffuse);
            if (!diffuse.is_black())
                set.add(Bsdf::lambert(Color(1, 1, 1)), diffuse, n, std::fabs(average(diffuse)));
            set.add(b);
            return;
        }
        case ClosureKind::Principled: break;
    }
    // Subsurface: the base colour mixed with the subsurface colour walks under the surface
    // in place of the diffuse lobe; after a diffuse bounce (Cycles' PATH_RAY_DIFFUSE_ANCESTOR)
    // the mixed colour is drawn as plain diffuse, and tints the other lobes too, as in Cycles.
    const double diffuse_weight = (1 - c.metallic) * (1 - c.transmission);
    const Color mixed = c.subsurface_color * c.subsurface + c.color * (1 - c.subsurface);
    const bool bssrdf = !diffuse_ancestor && c.subsurface > 1e-5 && diffuse_weight > 1e-5 &&
                        std::fabs(average(mixed)) > 1e-5;
    PrincipledParams p;
    p.base = diffuse_ancestor ? mixed : c.color;
    p.diffuse_lobe = !bssrdf;
    p.roughness = c.roughness;
    p.metallic = c.metallic;
    p.specular = c.specular;
    p.ior = c.ior;
    p.transmission = c.transmission;
    p.specular_tint = c.specular_tint;
    p.anisotropic = c.anisotropy;
    // Transmission roughness counts with the "GGX" distribution only (Cycles 3.4).
    p.transmission_roughness =
        c.distribution == Distribution::GGX
            ? 1 - (1 - c.roughness) * (1 - std::clamp(c.transmission_roughness, 0.0, 1.0))
            : c.roughness;
    // Multiscatter GGX: Cycles takes it for the reflection lobe above roughness 0.075, and
    // for the glass lobes above roughness 0.05 (one random walk with Fresnel tints in place
    // of the two).
    const bool multi = c.distribution == Distribution::MultiGGX && c.roughness > 0.075;
    const double glass_weight = std::clamp(c.transmission, 0.0, 1.0) *
                                (1 - std::clamp(c.metallic, 0.0, 1.0));
    const bool multi_glass = c.distribution == Distribution::MultiGGX && c.roughness > 0.05 &&
                             glass_weight > 1e-5;
    p.specular_lobe = !multi;
    p.glass_lobes = !multi_glass;
    const Bsdf main = Bsdf::principled(p);
    if (!main.empty()) set.add(main, w, n, share, tangent);
    if (multi && (c.specular > 1e-5 || c.metallic > 1e-5)) {
        const double spec_weight = 1 - (1 - c.metallic) * c.transmission;
        const double aspect = std::sqrt(std::max(0.0, 1 - 0.9 * std::clamp(c.anisotropy, 0.0, 1.0)));
        MultiGgx m{alpha / aspect, alpha * aspect, true, p.base, main.specular_cspec0(),
                   main.specular_eta()};
        const Color sw = w * spec_weight;
        set.add(Lobe::multi_ggx(m), sw, n, std::fabs(average(sw)), tangent);
    }
    if (multi_glass) {
        // Cycles' bsdf_microfacet_multi_ggx_glass_fresnel_setup: weighed by the transmission
        // alone, the base colour tinting refractions and the specular tint's cspec0 the
        // reflections.
        const double st = c.specular_tint;
        MultiGlass g{alpha, c.ior, p.base, true, p.base * st + Color(1 - st)};
        const Color gw = w * glass_weight;
        set.add(Lobe::multi_glass(g), gw, n, std::fabs(average(gw)));
    }
    if (bssrdf) {
        Bssrdf b;
        b.weight = w * mixed * diffuse_weight;
        b.radius = c.subsurface_radius * c.subsurface;
        b.albedo = mixed;
        b.anisotropy = std::clamp(c.subsurface_anisotropy, 0.0, 0.9);
        b.exit_fresnel = true;
        b.n = n;
        // Burley's retro-reflection stays a BSDF, with the BSSRDF's whole weight.
        const double share_b = std::fabs(average(b.weight));
        if (share_b >= 1e-5) {
            set.add(Lobe::retro_reflection(c.roughness), b.weight, n, share_b);
            Color diffuse;
            b.setup(c.subsurface_method != shader::SubsurfaceMethod::RandomWalk,
                    std::clamp(c.subsurface_ior, 1.01, 3.8), &diffuse);
            if (!diffuse.is_black())
                set.add(Lobe::burley_lambert(), diffuse, n, std::fabs(average(diffuse)));
            set.add(b);
        }
    }
    if (diffuse_weight > 1e-5 && c.sheen > 1e-5) {
        // Sheen tinted towards the base colour's hue (luminance by Rec. 709).
        const double lum = 0.2126729 * p.base.r + 0.7151522 * p.base.g + 0.0721750 * p.base.b;
        const Color hue = lum > 0 ? p.base * (1 / lum) : Color(1, 1, 1);
        const Color tint = Color(1 - c.sheen_tint) + hue * c.sheen_tint;
        const Color sw = w * tint * (c.sheen * diffuse_weight);
        set.add(Lobe::sheen(), sw, n, std::fabs(average(sw)));
    }
    if (c.clearcoat > 1e-5) {
        const Vec3 cn = length_squared(c.clearcoat_N) > 0 ? normalize(c.clearcoat_N) * outside : n;
        set.add(Lobe::clearcoat(c.clearcoat, c.clearcoat_roughness), w, cn,
                std::fabs(average(w)));
    }
}

}  // namespace glint::render
