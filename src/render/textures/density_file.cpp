#include "render/textures/density_file.h"

#include <cmath>

namespace glint::render {

double density_file(const scene::PatternParams& params, const Vec3& p) {
    const scene::DensityGrid* g = params.density_file.get();
    if (!g || g->values.empty()) return 0.0;
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1)) return 0.0;
    const size_t sx = static_cast<size_t>(g->nx), sy = static_cast<size_t>(g->ny),
                 sz = static_cast<size_t>(g->nz);
    auto at = [&](size_t x, size_t y, size_t z) { return g->values[(z * sy + y) * sx + x]; };
    double density = 0.0;
    switch (params.density_interpolate % 10) {
        case 0: {
            const size_t x = static_cast<size_t>(p.x * sx), y = static_cast<size_t>(p.y * sy),
                         z = static_cast<size_t>(p.z * sz);
            density = x < sx && y < sy && z < sz ? at(x, y, z) : 0.0;
            break;
        }
        case 1: {
            double xx = p.x * sx, yy = p.y * sy, zz = p.z * sz;
            const size_t x1 = static_cast<size_t>(xx), y1 = static_cast<size_t>(yy),
                         z1 = static_cast<size_t>(zz);
            const size_t x2 = (x1 + 1) % sx, y2 = (y1 + 1) % sy, z2 = (z1 + 1) % sz;
            xx -= std::floor(xx);
            yy -= std::floor(yy);
            zz -= std::floor(zz);
            const double xi = 1.0 - xx, yi = 1.0 - yy;
            density = ((at(x1, y1, z1) * xi + at(x2, y1, z1) * xx) * yi +
                       (at(x1, y2, z1) * xi + at(x2, y2, z1) * xx) * yy) * (1.0 - zz) +
                      ((at(x1, y1, z2) * xi + at(x2, y1, z2) * xx) * yi +
                       (at(x1, y2, z2) * xi + at(x2, y2, z2) * xx) * yy) * zz;
            break;
        }
        default: {
            auto wrap = [](long i, size_t n) {
                return i < 0 ? n - 1 : static_cast<size_t>(i) % n;
            };
            auto cubic = [](float t, float a, float b, float c, float d) {
                const float m = (c - a) * 0.5f, n = (d - b) * 0.5f;
                const float e = 2.0f * (b - c) + m + n, f = -3.0f * (b - c) - 2.0f * m - n;
                return ((e * t + f) * t + m) * t + b;
            };
            double xx = p.x * sx, yy = p.y * sy, zz = p.z * sz;
            const long x1 = static_cast<long>(xx), y1 = static_cast<long>(yy),
                       z1 = static_cast<long>(zz);
            xx -= std::floor(xx);
            yy -= std::floor(yy);
            zz -= std::floor(zz);
            size_t k[4];
            for (int i = 0; i < 4; ++i) k[i] = wrap(z1 - 1 + i, sz);
            float plane[4][4];
            for (int i = 0; i < 4; ++i) {
                const size_t ii = wrap(i + x1 - 1, sx);
                for (int j = 0; j < 4; ++j) {
                    const size_t jj = wrap(j + y1 - 1, sy);
                    plane[i][j] = cubic(static_cast<float>(zz), at(ii, jj, k[0]), at(ii, jj, k[1]),
                                        at(ii, jj, k[2]), at(ii, jj, k[3]));
                }
            }
            // (POV-Ray writes the y results over row 0 as it goes: kept.)
            for (int i = 0; i < 4; ++i)
                plane[0][i] = cubic(static_cast<float>(yy), plane[i][0], plane[i][1], plane[i][2],
                                    plane[i][3]);
            density = cubic(static_cast<float>(xx), plane[0][0], plane[0][1], plane[0][2],
                            plane[0][3]);
        }
    }
    return density < 0.0 ? 0.0 : density;
}

}  // namespace glint::render
