#include "app/parts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "render/film/film.h"

namespace glint::app {
namespace {

// Whole decimal numbers separated by `sep`, exactly `count` of them.
bool read_ints(const std::string& text, char sep, size_t count, std::vector<long long>* out) {
    out->clear();
    size_t i = 0;
    while (true) {
        size_t j = i;
        if (j < text.size() && text[j] == '-') ++j;
        const size_t digits = j;
        while (j < text.size() && text[j] >= '0' && text[j] <= '9') ++j;
        if (j == digits || j - digits > 9) return false;
        out->push_back(std::stoll(text.substr(i, j - i)));
        if (j == text.size()) break;
        if (text[j] != sep) return false;
        i = j + 1;
    }
    return out->size() == count;
}

}  // namespace

render::Region parse_region(const std::string& text, const std::string& flag) {
    std::vector<long long> v;
    if (!read_ints(text, ',', 4, &v))
        throw Error(ErrorKind::Usage, {},
                    flag + " " + text + ": expected x0,y0,x1,y1 (whole pixels: columns x0 to x1 - 1, "
                    "rows y0 to y1 - 1, from 0 at the top left)");
    render::Region r{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]),
                     static_cast<int>(v[3])};
    if (r.empty() || r.x0 < 0 || r.y0 < 0)
        throw Error(ErrorKind::Usage, {},
                    flag + " " + text + ": an empty rectangle (x1 must exceed x0 and y1 y0, "
                    "both from 0)");
    return r;
}

std::string region_string(const render::Region& r) {
    return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," +
           std::to_string(r.y1);
}

FrameRange parse_frame_range(const std::string& text, const std::string& flag) {
    std::vector<long long> v;
    FrameRange f;
    if (read_ints(text, '-', 1, &v) && v[0] >= 0) {
        f.first = f.last = static_cast<int>(v[0]);
        return f;
    }
    if (!read_ints(text, '-', 2, &v) || v[0] < 0 || v[1] < v[0])
        throw Error(ErrorKind::Usage, {},
                    flag + " " + text + ": expected FIRST-LAST frame numbers (0 or more, "
                    "FIRST <= LAST), or one number");
    f.first = static_cast<int>(v[0]);
    f.last = static_cast<int>(v[1]);
    return f;
}

std::vector<render::Region> split_into_tiles(int width, int height, int n) {
    if (n < 1) throw Error(ErrorKind::Usage, {}, "--tiles must be at least 1");
    if (static_cast<long long>(width) * height < n)
        throw Error(ErrorKind::Usage, {},
                    "--tiles " + std::to_string(n) + ": the " + std::to_string(width) + "x" +
                        std::to_string(height) + " image has fewer pixels than that");
    // Columns x rows = n, the pair whose tiles are nearest to square.
    int best_cols = 1;
    double best = 1e300;
    for (int cols = 1; cols <= n; ++cols) {
        if (n % cols != 0) continue;
        const int rows = n / cols;
        if (cols > width || rows > height) continue;
        const double aspect = (static_cast<double>(width) / cols) / (static_cast<double>(height) / rows);
        const double off = std::fabs(std::log(aspect));
        if (off < best) {
            best = off;
            best_cols = cols;
        }
    }
    if (best == 1e300)
        throw Error(ErrorKind::Usage, {},
                    "--tiles " + std::to_string(n) + ": no grid of that many tiles fits the " +
                        std::to_string(width) + "x" + std::to_string(height) + " image");
    const int cols = best_cols, rows = n / cols;
    // Edges: on block boundaries when there are at least as many blocks as tiles, else on
    // pixels; strictly increasing either way.
    auto edges = [](int size, int parts) {
        const int blocks = (size + render::kBlockSize - 1) / render::kBlockSize;
        std::vector<int> e(static_cast<size_t>(parts) + 1);
        for (int i = 0; i <= parts; ++i) {
            if (blocks >= parts)
                e[i] = std::min(size, static_cast<int>((static_cast<long long>(blocks) * i / parts)) *
                                          render::kBlockSize);
            else
                e[i] = static_cast<int>(static_cast<long long>(size) * i / parts);
        }
        e[parts] = size;
        return e;
    };
    const std::vector<int> xs = edges(width, cols), ys = edges(height, rows);
    std::vector<render::Region> tiles;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) tiles.push_back({xs[c], ys[r], xs[c + 1], ys[r + 1]});
    return tiles;
}

uint64_t fnv1a(const void* data, size_t size, uint64_t h) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

std::string job_signature(const std::string& settings, const std::string& scene_path) {
    uint64_t h = fnv1a(settings.data(), settings.size());
    std::ifstream in(scene_path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    h = fnv1a(bytes.data(), bytes.size(), h);
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

}  // namespace glint::app
