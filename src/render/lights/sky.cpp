#include "render/lights/sky.h"

#include <cmath>

namespace glint::render {

using scene::ColorFT;

Color sky_radiance(const scene::Scene& scene, const PigmentEvaluator& pigments, const Vec3& dir,
                   bool legacy) {
    const ColorFT& bg = scene.background;
    const scene::SkySphere* sky = scene.sky_sphere ? &*scene.sky_sphere : nullptr;
    Vec3 d = normalize(dir);
    if (legacy) {
        // ComputeSky for pre-3.7 scenes.
        if (!sky || sky->pigments.empty()) return bg.rgb;
        Vec3 p = sky->transform.is_identity() ? d : sky->transform.inverse_point(d);
        Color col;
        Color frgb(1.0);
        double ff = 1.0, ft = 1.0;
        double trans = 1.0;
        for (int i = static_cast<int>(sky->pigments.size()) - 1; i >= 0; --i) {
            ColorFT c;
            pigments.evaluate(sky->pigments[i], {p, {}, false}, &c);
            double att = trans * (1.0 - c.filter - c.transmit);
            col += c.rgb * att;
            frgb *= c.rgb;
            ff *= c.filter;
            ft *= c.transmit;
            trans = std::fabs(ff) + std::fabs(ft);
        }
        col *= sky->emission;
        return col + bg.rgb * (frgb * ff + Color(ft));
    }
    // 3.7: the sky sphere behaves like a layered texture over the background.
    Color col;
    Color fil(1.0);
    if (sky && !sky->pigments.empty()) {
        Vec3 p = sky->transform.is_identity() ? d : sky->transform.inverse_point(d);
        for (int i = static_cast<int>(sky->pigments.size()) - 1; i >= 0; --i) {
            ColorFT c;
            pigments.evaluate(sky->pigments[i], {p, {}, false}, &c);
            double att = 1.0 - c.filter - c.transmit;
            col += c.rgb * att * fil * sky->emission;
            fil *= Color(c.rgb.r * c.filter + c.transmit, c.rgb.g * c.filter + c.transmit,
                         c.rgb.b * c.filter + c.transmit);
        }
    }
    // Without an alpha channel the background's filter and transmit are ignored.
    col += bg.rgb * fil;
    return col;
}

}  // namespace glint::render
