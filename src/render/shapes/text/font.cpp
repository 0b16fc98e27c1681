// Reading TrueType fonts the way POV-Ray 3.7 reads them (truetype.cpp): FreeType decodes the
// glyph outlines; the layout numbers POV-Ray takes straight from the font's tables (glyph
// header bounds, hmtx advance and left side bearing, format 0 kern pairs, cmap choice) are
// read from the raw tables so that its quirks can be reproduced.
#include "render/shapes/text/font.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/error.h"

namespace glint::render {
namespace {

// truetype.cpp kern coverage bits.
constexpr unsigned kKernHorizontal = 0x01;
constexpr unsigned kKernMinimum = 0x02;
constexpr unsigned kKernCrossStream = 0x04;
constexpr unsigned kKernOverride = 0x08;

struct KernPair {
    unsigned left, right;
    int value;
};
struct KernTable {
    unsigned coverage = 0;
    std::vector<KernPair> pairs;
};

class Bytes {
public:
    Bytes() = default;
    explicit Bytes(std::vector<unsigned char> b) : b_(std::move(b)) {}
    size_t size() const { return b_.size(); }
    unsigned u16(size_t at) const {
        return at + 2 <= b_.size() ? (unsigned(b_[at]) << 8 | b_[at + 1]) : 0u;
    }
    int s16(size_t at) const { return static_cast<int16_t>(u16(at)); }
    unsigned long u32(size_t at) const { return (unsigned long)u16(at) << 16 | u16(at + 2); }

private:
    std::vector<unsigned char> b_;
};

class FontFile {
public:
    explicit FontFile(const std::string& path) : path_(path) {
        // A constructor that throws runs no destructor: free FreeType here (LeakSanitizer
        // found the library leaking for every unreadable font).
        try {
            open();
        } catch (...) {
            release();
            throw;
        }
    }
    ~FontFile() { release(); }
    FontFile(const FontFile&) = delete;
    FontFile& operator=(const FontFile&) = delete;

private:
    void open() {
        if (FT_Init_FreeType(&lib_)) fail("cannot start FreeType");
        if (FT_New_Face(lib_, path_.c_str(), 0, &face_)) fail("not a readable TrueType font");
        if (!FT_IS_SFNT(face_)) fail("not a TrueType font");
        head_ = table(TTAG_head);
        if (head_.size() < 54) fail("the font has no 'head' table");
        units_per_em_ = head_.u16(18);
        if (units_per_em_ == 0) fail("the font's unitsPerEm is 0");
        long_loca_ = head_.s16(50) != 0;
        loca_ = table(TTAG_loca);
        glyf_ = table(TTAG_glyf);
        Bytes hhea = table(TTAG_hhea);
        Bytes maxp = table(TTAG_maxp);
        hmtx_ = table(TTAG_hmtx);
        num_hmetrics_ = hhea.u16(34);
        num_glyphs_ = maxp.u16(4);
        if (num_hmetrics_ == 0) fail("the font has no horizontal metrics");
        read_kern();
        choose_charmap();
    }
    void release() {
        if (face_) FT_Done_Face(face_);
        if (lib_) FT_Done_FreeType(lib_);
        face_ = nullptr;
        lib_ = nullptr;
    }

public:

    double units_per_em() const { return units_per_em_; }

    // ProcessCharMap: the first cmap subtable of the preferred platform (Macintosh, then
    // Microsoft, then Unicode) in format 0, 4 or 6 answers, even when it says "missing".
    unsigned glyph_index(unsigned c) const {
        if (!charmap_) return 0;
        FT_Set_Charmap(face_, charmap_);
        unsigned gi = FT_Get_Char_Index(face_, c);
        // Format 4: symbol fonts keep their characters in the private use area at 0xF000.
        if (gi == 0 && c < 0x100 && charmap_format_ == 4) gi = FT_Get_Char_Index(face_, c + 0xF000);
        return gi;
    }

    unsigned advance(unsigned gi) const {
        unsigned i = std::min(gi, num_hmetrics_ - 1);
        return hmtx_.u16(4 * i);
    }
    int lsb(unsigned gi) const {
        if (gi < num_hmetrics_) return hmtx_.s16(4 * gi + 2);
        return hmtx_.s16(4 * num_hmetrics_ + 2 * (gi - num_hmetrics_));
    }

    // ProcessNewTTF's kerning for the pair (left, right), horizontal and cross-stream.
    void kerning(unsigned left, unsigned right, int* kx, int* ky) const {
        int x = 0, y = 0;
        int min_x = -static_cast<int>(units_per_em_), min_y = min_x;
        for (const KernTable& t : kern_) {
            // POV-Ray reads the coverage of the first subtable for every subtable.
            unsigned coverage = kern_.front().coverage;
            if (!(coverage & kKernHorizontal)) continue;
            for (const KernPair& p : t.pairs) {
                if (p.left == left && p.right == right) {
                    if (coverage & kKernMinimum) {
                        (coverage & kKernCrossStream ? min_y : min_x) = p.value;
                    } else if (coverage & kKernCrossStream) {
                        if (p.value == -0x8000) y = 0;
                        else y = coverage & kKernOverride ? p.value : y + p.value;
                    } else {
                        x = coverage & kKernOverride ? p.value : x + p.value;
                    }
                    break;
                }
                if (p.left > left) break;
            }
        }
        *kx = std::max(x, min_x);
        *ky = std::max(y, min_y);
    }

    // ExtractGlyphOutline + ConvertOutlineToGlyph: contours in em units, and the glyph's xMin
    // in font units as POV-Ray computes it (header value lowered by the points).
    Glyph outline(unsigned gi, unsigned c, int* x_min) const {
        Glyph g;
        *x_min = 0;
        if (c == ' ') return g;  // POV-Ray never reads a space's outline
        size_t off = glyph_offset(gi);
        if (off == size_t(-1) || off + 10 > glyf_.size()) return g;
        int num_contours = glyf_.s16(off);
        int hdr_x_min = glyf_.s16(off + 2);
        if (FT_Load_Glyph(face_, gi, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
            return g;
        const FT_Outline& o = face_->glyph->outline;
        // FreeType moves the outline so that the glyph origin is at 0: x - (xMin - lsb).
        const double shift = hdr_x_min - lsb(gi);
        const double em = units_per_em_;
        int xmin = hdr_x_min;
        int start = 0;
        bool first = true;
        double area = 0;
        for (int k = 0; k < o.n_contours; ++k) {
            GlyphContour ct;
            int end = o.contours[k];
            for (int i = start; i <= end; ++i) {
                double fx = o.points[i].x + shift;
                double x = fx / em, y = o.points[i].y / em;
                if (num_contours >= 0) {
                    if (fx < xmin) xmin = static_cast<int>(fx);
                } else if (x < xmin) {
                    // Composite glyphs: POV-Ray compares em units with the font-unit header
                    // value and stores the em value in a 16-bit integer.
                    xmin = static_cast<int16_t>(static_cast<int>(x));
                }
                ct.p.push_back({x, y});
                ct.on_curve.push_back(FT_CURVE_TAG(o.tags[i]) == FT_CURVE_TAG_ON);
                if (first) {
                    g.lo = g.hi = Vec2(x, y);
                    first = false;
                }
                g.lo = Vec2(std::min(g.lo.x, x), std::min(g.lo.y, y));
                g.hi = Vec2(std::max(g.hi.x, x), std::max(g.hi.y, y));
            }
            start = end + 1;
            if (ct.p.empty()) continue;
            ct.p.push_back(ct.p.front());
            ct.on_curve.push_back(ct.on_curve.front());
            for (size_t i = 0; i + 1 < ct.p.size(); ++i)
                area += ct.p[i].x * ct.p[i + 1].y - ct.p[i + 1].x * ct.p[i].y;
            g.contours.push_back(std::move(ct));
        }
        // TrueType fills right of the contour direction (clockwise outer contours).
        g.winding = area <= 0 ? 1.0 : -1.0;
        *x_min = xmin;
        return g;
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        throw Error(ErrorKind::MissingFile, FileLoc{}, "cannot read the font '" + path_ + "': " + why);
    }

    Bytes table(FT_ULong tag) const {
        FT_ULong len = 0;
        if (FT_Load_Sfnt_Table(face_, tag, 0, nullptr, &len) || len == 0) return {};
        std::vector<unsigned char> b(len);
        if (FT_Load_Sfnt_Table(face_, tag, 0, b.data(), &len)) return {};
        return Bytes(std::move(b));
    }

    size_t glyph_offset(unsigned gi) const {
        if (long_loca_) {
            if (4 * (gi + 1) + 4 > loca_.size()) return size_t(-1);
            return loca_.u32(4 * gi);
        }
        if (2 * gi + 2 > loca_.size()) return size_t(-1);
        return 2 * size_t(loca_.u16(2 * gi));
    }

    void read_kern() {
        Bytes k = table(TTAG_kern);
        if (k.size() < 4) return;
        unsigned n = k.u16(2);
        size_t at = 4;
        for (unsigned i = 0; i < n && at + 6 <= k.size(); ++i) {
            KernTable t;
            unsigned length = k.u16(at + 2);
            t.coverage = k.u16(at + 4);
            if ((t.coverage >> 8) == 0) {
                unsigned pairs = k.u16(at + 6);
                size_t p = at + 14;
                for (unsigned j = 0; j < pairs && p + 6 <= k.size(); ++j, p += 6)
                    t.pairs.push_back({k.u16(p), k.u16(p + 2), k.s16(p + 4)});
                at = p;
            } else {
                at += std::max(length, 6u);
            }
            kern_.push_back(std::move(t));
        }
    }

    void choose_charmap() {
        static constexpr int kPlatforms[] = {1, 3, 0, 3};
        for (int platform : kPlatforms) {
            for (int i = 0; i < face_->num_charmaps; ++i) {
                FT_CharMap cm = face_->charmaps[i];
                if (cm->platform_id != platform) continue;
                long format = FT_Get_CMap_Format(cm);
                if (format == 0 || format == 4 || format == 6) {
                    charmap_ = cm;
                    charmap_format_ = format;
                    return;
                }
            }
        }
    }

    std::string path_;
    FT_Library lib_ = nullptr;
    FT_Face face_ = nullptr;
    Bytes head_, loca_, glyf_, hmtx_;
    unsigned units_per_em_ = 0;
    bool long_loca_ = false;
    unsigned num_hmetrics_ = 0, num_glyphs_ = 0;
    std::vector<KernTable> kern_;
    FT_CharMap charmap_ = nullptr;
    long charmap_format_ = -1;
};

}  // namespace

TextGlyphs layout_text(const std::string& font_path, const std::string& text, const Vec3& offset) {
    FontFile font(font_path);
    TextGlyphs out;
    const double funit = 1.0 / font.units_per_em();
    Vec3 total(0, 0, 0);
    unsigned last_index = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        unsigned c = static_cast<unsigned char>(text[i]);
        unsigned gi = font.glyph_index(c);
        int x_min = 0;
        Glyph g = font.outline(gi, c, &x_min);
        if (i == 0) {
            // The first glyph starts at the origin; the next one a width past its left edge.
            g.offset = Vec2(-x_min * funit, 0);
            total.x = (static_cast<int>(font.advance(gi)) - font.lsb(gi)) * funit;
        } else {
            int kx, ky;
            font.kerning(last_index, gi, &kx, &ky);
            g.offset = Vec2(total.x + (font.lsb(gi) - x_min + kx) * funit, total.y + ky * funit);
            total.x += (static_cast<int>(font.advance(gi)) + kx) * funit;
        }
        total += offset;
        last_index = gi;
        out.glyphs.push_back(std::move(g));
    }
    return out;
}

}  // namespace glint::render
