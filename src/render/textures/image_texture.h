// Images behind image_map pigments: read once per render through OpenImageIO (only when the
// scene uses image maps), decoded into POV-Ray's working color space, and looked up with
// POV-Ray 3.7's mapping and interpolation rules (source/backend/support/imageutil.cpp).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "core/log.h"
#include "scene/scene.h"

namespace glint::render {

// How 8-bit (and other) image files are decoded, from the scene's #version and
// assumed_gamma (POV-Ray 3.7 parser: gammaMode in tokenize.cpp/parse.cpp).
struct ImageGamma {
    enum class Mode {
        None,      // pre-3.7 scene without assumed_gamma: file values used as stored
        Legacy36,  // pre-3.7 scene with assumed_gamma: files are taken to be in working gamma
        V37,       // 3.7 scene: decode the file's gamma (sRGB by default), encode working gamma
    };
    Mode mode = Mode::V37;
    double working_gamma = 1.0;
};

ImageGamma image_gamma(const scene::Scene& scene);

// IEC 61966-2-1's decoding curve, the default file gamma of 8-bit images in POV-Ray 3.7.
double srgb_decode(double v);

class ImageTexture {
public:
    int width() const { return width_; }
    int height() const { return height_; }
    // Texel (x, y), row 0 at the top: r, g, b, filter, transmit (transmit = 1 - alpha).
    const float* texel(int x, int y) const {
        return &data_[(static_cast<size_t>(y) * width_ + x) * 5];
    }
    // Whether the file has an alpha channel (otherwise transmit is 0 everywhere).
    bool has_alpha() const { return has_alpha_; }
    // Whether the file holds 8-bit values in the sRGB encoding (8 bits a channel and no gamma
    // of its own), whatever this texture decoded them to.
    bool srgb8() const { return srgb8_; }
    // Palette images: the entries' count, and texel (x, y)'s index.
    bool indexed() const { return palette_size_ > 0; }
    int palette_size() const { return palette_size_; }
    int index(int x, int y) const { return indices_[static_cast<size_t>(y) * width_ + x]; }

    // Throws Error(MissingFile) if the file cannot be read.
    static std::shared_ptr<const ImageTexture> load(const scene::ImageMap& map,
                                                    const ImageGamma& gamma);

private:
    int width_ = 0;
    int height_ = 0;
    bool has_alpha_ = false;
    bool srgb8_ = false;
    int palette_size_ = 0;
    std::vector<float> data_;
    std::vector<uint8_t> indices_;  // palette images only
};

// All images of one render, keyed by resolved path and gamma override; filled at prepare time
// so the render threads only read.
class TextureCache {
public:
    explicit TextureCache(ImageGamma gamma) : gamma_(gamma) {}
    // Loads every image map reachable from the scene's materials and sky sphere.
    void preload(const scene::Scene& scene);
    // nullptr if `map` was not preloaded.
    const ImageTexture* find(const scene::ImageMap& map) const;
    size_t size() const { return images_.size() + pbr_images_.size(); }

    // PBR maps (OBJ/MTL) for the path tracer, in linear values whatever the scene's gamma:
    // `color` maps (map_Kd, map_Ks, map_Ke) decoded from sRGB (or the file's own gamma), data
    // maps (roughness, metallic, alpha, bump, ...) read as stored. Loaded on first add; throws
    // Error(MissingFile) if a file that exists cannot be decoded. Maps without a resolved file
    // (the importer warned) are skipped; find_pbr() gives nullptr for them.
    void add_pbr(const scene::PbrMap& map, bool color);
    const ImageTexture* find_pbr(const scene::PbrMap& map, bool color) const;

private:
    // find() runs for every image_map evaluation: it looks up by a view of the path, so a
    // lookup builds no string.
    struct KeyView {
        std::string_view path;
        double gamma;
        bool data = false;  // scene::ImageMap::data
    };
    struct Key {
        std::string path;
        double gamma;
        bool data = false;
        operator KeyView() const { return {path, gamma, data}; }
    };
    struct KeyLess {
        using is_transparent = void;
        bool operator()(KeyView a, KeyView b) const {
            if (a.path != b.path) return a.path < b.path;
            return a.gamma != b.gamma ? a.gamma < b.gamma : a.data < b.data;
        }
    };
    void add(const scene::ImageMap& map);
    static KeyView key(const scene::ImageMap& map);
    ImageGamma gamma_;
    std::map<Key, std::shared_ptr<const ImageTexture>, KeyLess> images_;
    std::map<Key, std::shared_ptr<const ImageTexture>, KeyLess> pbr_images_;  // gamma: 1 color, 0 data
};

}  // namespace glint::render
