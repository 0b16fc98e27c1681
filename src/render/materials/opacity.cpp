#include "render/materials/opacity.h"

#include "render/textures/image_texture.h"

namespace glint::render {

bool pigment_can_be_transparent(const scene::Pigment& p, const TextureCache* textures) {
    if (p.kind == scene::PatternKind::Plain) return !p.color.opaque();
    if (p.kind == scene::PatternKind::ImageMap) {
        const scene::ImageMap& im = p.params.image;
        // `once`: clear beyond the image.
        if (im.once || im.filter_all != 0 || im.transmit_all != 0 || !im.palette_edits.empty() ||
            !textures)
            return true;
        const ImageTexture* image = textures->find(im);
        return !image || image->has_alpha();
    }
    for (const scene::ColorMapEntry& e : p.color_map)
        if (!e.color.opaque()) return true;
    for (const scene::PigmentMapEntry& e : p.pigment_map)
        if (pigment_can_be_transparent(e.pigment[0], textures)) return true;
    for (const scene::Pigment& e : p.entries)
        if (pigment_can_be_transparent(e, textures)) return true;
    return false;
}

bool texture_can_be_transparent(const scene::Texture& t, const TextureCache* textures) {
    if (t.kind == scene::PatternKind::Plain) {
        if (!pigment_can_be_transparent(t.pigment, textures)) return false;
        for (const scene::Texture& l : t.layers)
            if (!pigment_can_be_transparent(l.pigment, textures)) return false;
        return true;
    }
    for (const scene::TextureMapEntry& e : t.texture_map)
        if (texture_can_be_transparent(e.texture[0], textures)) return true;
    for (const scene::Texture& e : t.entries)
        if (texture_can_be_transparent(e, textures)) return true;
    return false;
}

}  // namespace glint::render
