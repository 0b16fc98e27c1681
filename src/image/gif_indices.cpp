#include "image/gif_indices.h"

#include <fstream>
#include <iterator>

namespace glint {
namespace {

// GIF's variable-width LZW (codes of min_bits + 1 up to 12 bits, least significant bit first).
bool lzw_decode(const std::vector<uint8_t>& data, int min_bits, size_t want,
                std::vector<uint8_t>* out) {
    if (min_bits < 2 || min_bits > 8) return false;
    const int clear = 1 << min_bits, end = clear + 1;
    std::vector<uint16_t> prefix(4096);
    std::vector<uint8_t> suffix(4096), stack;
    stack.reserve(4096);
    for (int i = 0; i < clear; ++i) suffix[i] = static_cast<uint8_t>(i);
    int bits = min_bits + 1, next = end + 1, prev = -1;
    uint8_t first = 0;
    size_t pos = 0;  // bit position
    while (out->size() < want) {
        if (pos + bits > data.size() * 8) break;
        int code = 0;
        for (int b = 0; b < bits; ++b, ++pos)
            code |= ((data[pos >> 3] >> (pos & 7)) & 1) << b;
        if (code == clear) {
            bits = min_bits + 1;
            next = end + 1;
            prev = -1;
            continue;
        }
        if (code == end) break;
        if (prev < 0) {
            if (code >= clear) return false;
            out->push_back(static_cast<uint8_t>(code));
            first = static_cast<uint8_t>(code);
            prev = code;
            continue;
        }
        int c = code;
        if (code > next || (code == next && next >= 4096)) return false;
        if (code == next) {  // the code being defined: the previous string plus its first byte
            stack.push_back(first);
            c = prev;
        }
        while (c >= clear) {
            stack.push_back(suffix[c]);
            c = prefix[c];
        }
        stack.push_back(static_cast<uint8_t>(c));
        first = static_cast<uint8_t>(c);
        while (!stack.empty()) {
            out->push_back(stack.back());
            stack.pop_back();
        }
        if (next < 4096) {
            prefix[next] = static_cast<uint16_t>(prev);
            suffix[next] = first;
            ++next;
            if (next == (1 << bits) && bits < 12) ++bits;
        }
        prev = code;
    }
    if (out->size() > want) out->resize(want);
    return out->size() == want;
}

}  // namespace

bool read_gif_indices(const std::string& path, GifIndices* out, std::string* error) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        *error = "cannot open the file";
        return false;
    }
    const std::vector<uint8_t> d((std::istreambuf_iterator<char>(f)),
                                 std::istreambuf_iterator<char>());
    auto fail = [&](const char* why) {
        *error = why;
        return false;
    };
    if (d.size() < 13 || d[0] != 'G' || d[1] != 'I' || d[2] != 'F') return fail("not a GIF file");
    size_t i = 13;
    if (d[10] & 0x80) i += 3 * (size_t(2) << (d[10] & 7));
    // Sub-blocks (a length byte, then that many bytes) up to a zero length; appended to `data`.
    auto blocks = [&](std::vector<uint8_t>* data) {
        while (i < d.size()) {
            const size_t n = d[i++];
            if (n == 0) return true;
            if (i + n > d.size()) return false;
            if (data) data->insert(data->end(), d.begin() + i, d.begin() + i + n);
            i += n;
        }
        return false;
    };
    while (i < d.size()) {
        const uint8_t kind = d[i++];
        if (kind == '!') {
            if (i >= d.size()) break;
            ++i;  // the extension's label
            if (!blocks(nullptr)) break;
        } else if (kind == ',') {
            if (i + 10 > d.size()) break;
            out->width = d[i + 4] | d[i + 5] << 8;
            out->height = d[i + 6] | d[i + 7] << 8;
            const uint8_t flags = d[i + 8];
            i += 9;
            if (flags & 0x40) return fail("interlaced GIF images are not supported");
            if (flags & 0x80) i += 3 * (size_t(2) << (flags & 7));
            if (i >= d.size()) break;
            const int min_bits = d[i++];
            std::vector<uint8_t> data;
            if (!blocks(&data)) break;
            const size_t want = static_cast<size_t>(out->width) * out->height;
            out->index.clear();
            out->index.reserve(want);
            if (!lzw_decode(data, min_bits, want, &out->index))
                return fail("corrupt GIF image data");
            return true;
        } else {
            break;
        }
    }
    return fail("no image data in the GIF file");
}

}  // namespace glint
