#include "image/palette.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

namespace glint {

std::vector<PaletteColor> read_palette(const std::string& path) {
    std::vector<PaletteColor> table;
    std::ifstream f(path, std::ios::binary);
    std::vector<unsigned char> d((std::istreambuf_iterator<char>(f)),
                                 std::istreambuf_iterator<char>());
    auto be32 = [&](size_t i) {
        return uint32_t(d[i]) << 24 | uint32_t(d[i + 1]) << 16 | uint32_t(d[i + 2]) << 8 | d[i + 3];
    };
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
    if (d.size() > 33 && std::equal(kPng, kPng + 8, d.begin())) {
        if (d[25] != 3) return table;  // IHDR colour type: not a palette image
        for (size_t i = 8; i + 8 <= d.size();) {
            size_t len = be32(i);
            if (i + 12 + len > d.size()) break;
            if (std::equal(d.begin() + i + 4, d.begin() + i + 8, "PLTE")) {
                for (size_t k = 0; k + 3 <= len; k += 3)
                    table.push_back({d[i + 8 + k], d[i + 9 + k], d[i + 10 + k]});
                break;
            }
            i += 12 + len;
        }
    } else if (d.size() > 13 && d[0] == 'G' && d[1] == 'I' && d[2] == 'F' && (d[10] & 0x80)) {
        size_t n = size_t(2) << (d[10] & 7);
        for (size_t k = 0; k < n && 13 + 3 * k + 3 <= d.size(); ++k)
            table.push_back({d[13 + 3 * k], d[14 + 3 * k], d[15 + 3 * k]});
    }
    return table;
}

int palette_index(const std::vector<PaletteColor>& palette, const float* pixel, int channels) {
    PaletteColor c{};
    for (int k = 0; k < 3; ++k)
        c[k] = static_cast<uint8_t>(std::round(pixel[std::min(k, channels - 1)] * 255.0));
    auto it = std::find(palette.begin(), palette.end(), c);
    return it != palette.end() ? static_cast<int>(it - palette.begin()) : c[0];
}

}  // namespace glint
