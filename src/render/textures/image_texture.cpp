#include "render/textures/image_texture.h"


#include <cmath>

#include "core/error.h"
#include "image/palette.h"
#include "image/png_reader.h"
#include "image/image_limits.h"
#include "core/quiet_stderr.h"

namespace glint::render {

double srgb_decode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

namespace {

void collect(const scene::Pigment& p, std::vector<const scene::ImageMap*>* out);

// The images a pattern itself reads: image_pattern's, and those of pigment_pattern's pigment.
void collect(scene::PatternKind kind, const scene::PatternParams& pp,
             std::vector<const scene::ImageMap*>* out) {
    if (kind == scene::PatternKind::ImagePattern) out->push_back(&pp.image);
    if (pp.pigment) collect(*pp.pigment, out);
}

// Collects image maps from a pigment tree.
void collect(const scene::Pigment& p, std::vector<const scene::ImageMap*>* out) {
    if (p.kind == scene::PatternKind::ImageMap) out->push_back(&p.params.image);
    collect(p.kind, p.params, out);
    for (const scene::Pigment& e : p.entries) collect(e, out);
    for (const scene::PigmentMapEntry& e : p.pigment_map) collect(e.pigment[0], out);
}

// ... from a normal tree (bump_map) ...
void collect(const scene::Normal& n, std::vector<const scene::ImageMap*>* out) {
    if (n.kind == scene::PatternKind::ImageMap) out->push_back(&n.params.image);
    collect(n.kind, n.params, out);
    for (const scene::Normal& e : n.entries) collect(e, out);
    for (const scene::NormalMapEntry& e : n.normal_map) collect(e.normal[0], out);
}

// ... and from a texture: its material_map image, layers, texture_map and block entries.
void collect(const scene::Texture& t, std::vector<const scene::ImageMap*>* out) {
    if (t.kind == scene::PatternKind::ImageMap) out->push_back(&t.params.image);
    collect(t.kind, t.params, out);
    collect(t.pigment, out);
    collect(t.normal, out);
    for (const scene::Texture& l : t.layers) collect(l, out);
    for (const scene::TextureMapEntry& e : t.texture_map) collect(e.texture[0], out);
    for (const scene::Texture& e : t.entries) collect(e, out);
}

}  // namespace

ImageGamma image_gamma(const scene::Scene& scene) {
    ImageGamma g;
    if (scene.global.assumed_gamma) {
        g.working_gamma = *scene.global.assumed_gamma;
        g.mode = scene.version < 3.7 ? ImageGamma::Mode::Legacy36 : ImageGamma::Mode::V37;
    } else if (scene.version < 3.7) {
        g.mode = ImageGamma::Mode::None;
        g.working_gamma = 1.0;
    } else {
        g.mode = ImageGamma::Mode::V37;
        g.working_gamma = 1.0;
    }
    return g;
}

std::shared_ptr<const ImageTexture> ImageTexture::load(const scene::ImageMap& map,
                                                       const ImageGamma& gamma) {
    const std::string& path = map.resolved_path.empty() ? map.file : map.resolved_path;
    std::string why;
    QuietStderr quiet;  // libpng's own lines: glint's error says what went wrong
    // POV-Ray works with unassociated alpha for PNG and friends.
    std::unique_ptr<ImageReader> in =
        open_image(path, {{"oiio:UnassociatedAlpha", 1}}, &why);
    if (!in) {
        throw Error(ErrorKind::MissingFile, map.loc,
                    "cannot read image '" + map.file + "': " + first_line_of(why));
    }
    const ImageHeader& spec = in->header();
    int w = spec.width, h = spec.height, nc = spec.channels;
    if (w <= 0 || h <= 0 || nc <= 0) {
        throw Error(ErrorKind::MissingFile, map.loc, "image '" + map.file + "' is empty");
    }
    check_image_size(w, h, nc, map.file, map.loc);
    std::vector<float> raw(static_cast<size_t>(w) * h * nc);
    why = in->read(nc, raw.data());
    if (!why.empty()) {
        throw Error(ErrorKind::MissingFile, map.loc,
                    "cannot decode image '" + map.file + "': " + first_line_of(why));
    }
    bool is_float = is_float_pixel(spec.type);
    int alpha_channel = spec.alpha_channel;
    if (alpha_channel < 0 && (nc == 2 || nc == 4)) alpha_channel = nc - 1;
    int color_channels = nc >= 3 ? 3 : 1;
    std::string colorspace = spec.colorspace;
    float file_gamma = spec.gamma;
    const bool tabulate = spec.type == PixelType::UInt8;
    in.reset();
    const std::vector<PaletteColor> palette = read_palette(path);

    // Transfer function from file values to the working space (POV-Ray 3.7 parstxtr.cpp,
    // Parse_Image: defaultGamma / workingGamma per gamma mode; `gamma G` overrides).
    auto decode = [&](double v) -> double {
        if (is_float) return v;  // linear formats are not gamma-adjusted
        if (map.data) {  // no default decoding and no working gamma; `gamma G` still decodes
            if (map.gamma > 0) return std::pow(std::max(v, 0.0), map.gamma);
            if (map.gamma < 0) return srgb_decode(v);
            return v;
        }
        double linear;
        if (map.gamma > 0) {
            linear = std::pow(std::max(v, 0.0), map.gamma);
        } else {
            switch (gamma.mode) {
                case ImageGamma::Mode::None: return v;
                case ImageGamma::Mode::Legacy36:
                    if (file_gamma > 0 && colorspace != "sRGB") {
                        linear = std::pow(std::max(v, 0.0), static_cast<double>(file_gamma));
                        break;
                    }
                    return v;  // default gamma = working gamma: values are used as stored
                case ImageGamma::Mode::V37:
                default:
                    if (file_gamma > 0 && colorspace != "sRGB" && colorspace.rfind("Gamma", 0) == 0)
                        linear = std::pow(std::max(v, 0.0), static_cast<double>(file_gamma));
                    else
                        linear = srgb_decode(v);
                    break;
            }
        }
        if (gamma.mode == ImageGamma::Mode::None || gamma.working_gamma == 1.0) return linear;
        return std::pow(std::max(linear, 0.0), 1.0 / gamma.working_gamma);
    };
    // 8-bit images have 256 distinct values: tabulate the transfer function.
    float table[256];
    if (tabulate)
        for (int i = 0; i < 256; ++i) table[i] = static_cast<float>(decode(i / 255.0));
    auto convert = [&](float v) -> float {
        if (tabulate) {
            int i = static_cast<int>(std::lround(v * 255.0f));
            return table[std::clamp(i, 0, 255)];
        }
        return static_cast<float>(decode(v));
    };

    auto tex = std::make_shared<ImageTexture>();
    tex->width_ = w;
    tex->height_ = h;
    tex->has_alpha_ = alpha_channel >= 0;
    tex->srgb8_ = tabulate &&
                  !(file_gamma > 0 && colorspace != "sRGB" && colorspace.rfind("Gamma", 0) == 0);
    tex->data_.resize(static_cast<size_t>(w) * h * 5);
    for (size_t i = 0; i < static_cast<size_t>(w) * h; ++i) {
        const float* s = &raw[i * nc];
        float* d = &tex->data_[i * 5];
        if (color_channels == 3) {
            d[0] = convert(s[0]);
            d[1] = convert(s[1]);
            d[2] = convert(s[2]);
        } else {
            d[0] = d[1] = d[2] = convert(s[0]);
        }
        d[3] = 0;  // filter
        d[4] = alpha_channel >= 0 ? 1.0f - s[alpha_channel] : 0.0f;  // transmit
    }
    if (!palette.empty()) {
        tex->palette_size_ = static_cast<int>(palette.size());
        tex->indices_.resize(static_cast<size_t>(w) * h);
        for (size_t i = 0; i < tex->indices_.size(); ++i)
            tex->indices_[i] = static_cast<uint8_t>(palette_index(palette, &raw[i * nc], nc));
    }
    return tex;
}

TextureCache::KeyView TextureCache::key(const scene::ImageMap& map) {
    return {map.resolved_path.empty() ? map.file : map.resolved_path, map.gamma, map.data};
}

void TextureCache::add(const scene::ImageMap& map) {
    KeyView k = key(map);
    auto it = images_.find(k);
    if (it == images_.end())
        it = images_
                 .emplace(Key{std::string(k.path), k.gamma, k.data}, ImageTexture::load(map, gamma_))
                 .first;
    // POV-Ray's parser reads the image and stops on these; glint reads images here.
    const ImageTexture& image = *it->second;
    for (const scene::ImageMap::PaletteEdit& e : map.palette_edits) {
        if (e.index < 0) continue;
        const char* what = e.filter ? "filter" : "transmit";
        if (!image.indexed())
            throw Error(ErrorKind::Scene, e.loc,
                        std::string(what) + " N, V sets a palette entry, and image '" +
                            map.file + "' has no palette (use '" + what + " all')");
        if (e.index >= image.palette_size())
            throw Error(ErrorKind::Scene, e.loc,
                        std::string(what) + " colour register " + std::to_string(e.index) +
                            " is out of range: image '" + map.file + "' has " +
                            std::to_string(image.palette_size()) + " palette entries");
    }
}

void TextureCache::preload(const scene::Scene& scene) {
    std::vector<const scene::ImageMap*> maps;
    auto media = [&](const std::vector<scene::Media>& list) {
        for (const scene::Media& md : list)
            for (const scene::Pigment& d : md.density) collect(d, &maps);
    };
    for (const scene::Material& m : scene.materials) {
        collect(m.texture, &maps);
        for (const scene::Texture& t : m.interior_texture) collect(t, &maps);
        media(m.interior.media);
    }
    media(scene.media);
    for (const scene::Function& f : scene.functions)
        for (const scene::Pigment& p : f.pigment) collect(p, &maps);
    if (scene.sky_sphere)
        for (const scene::Pigment& p : scene.sky_sphere->pigments) collect(p, &maps);
    collect(scene.camera.normal, &maps);
    for (const scene::ImageMap* m : maps) add(*m);
}

void TextureCache::add_pbr(const scene::PbrMap& map, bool color) {
    if (!map.present()) return;
    const KeyView k{map.resolved_path, color ? 1.0 : 0.0};
    if (pbr_images_.find(k) != pbr_images_.end()) return;
    scene::ImageMap im;
    im.file = map.file;
    im.resolved_path = map.resolved_path;
    im.loc = map.loc;
    im.gamma = color ? 0.0 : 1.0;  // 0: the file's gamma (sRGB by default); 1: as stored
    const ImageGamma linear{ImageGamma::Mode::V37, 1.0};
    pbr_images_.emplace(Key{map.resolved_path, k.gamma}, ImageTexture::load(im, linear));
}

const ImageTexture* TextureCache::find_pbr(const scene::PbrMap& map, bool color) const {
    auto it = pbr_images_.find(KeyView{map.resolved_path, color ? 1.0 : 0.0});
    return it == pbr_images_.end() ? nullptr : it->second.get();
}

const ImageTexture* TextureCache::find(const scene::ImageMap& map) const {
    auto it = images_.find(key(map));
    return it == images_.end() ? nullptr : it->second.get();
}

}  // namespace glint::render
