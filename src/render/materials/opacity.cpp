#include "render/materials/opacity.h"

namespace glint::render {

bool pigment_can_be_transparent(const scene::Pigment& p) {
    if (p.kind == scene::PatternKind::Plain) return !p.color.opaque();
    if (p.kind == scene::PatternKind::ImageMap) return true;  // alpha, filter/transmit all
    for (const scene::ColorMapEntry& e : p.color_map)
        if (!e.color.opaque()) return true;
    for (const scene::PigmentMapEntry& e : p.pigment_map)
        if (pigment_can_be_transparent(e.pigment[0])) return true;
    for (const scene::Pigment& e : p.entries)
        if (pigment_can_be_transparent(e)) return true;
    return false;
}

bool texture_can_be_transparent(const scene::Texture& t) {
    if (t.kind == scene::PatternKind::Plain) {
        if (!pigment_can_be_transparent(t.pigment)) return false;
        for (const scene::Texture& l : t.layers)
            if (!pigment_can_be_transparent(l.pigment)) return false;
        return true;
    }
    for (const scene::TextureMapEntry& e : t.texture_map)
        if (texture_can_be_transparent(e.texture[0])) return true;
    for (const scene::Texture& e : t.entries)
        if (texture_can_be_transparent(e)) return true;
    return false;
}

}  // namespace glint::render
