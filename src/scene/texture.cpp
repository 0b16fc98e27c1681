#include "scene/texture.h"

namespace glint::scene {

const char* pattern_name(PatternKind kind) {
    switch (kind) {
        case PatternKind::Plain: return "plain";
        case PatternKind::Checker: return "checker";
        case PatternKind::Gradient: return "gradient";
        case PatternKind::ImageMap: return "image_map";
        case PatternKind::Agate: return "agate";
        case PatternKind::Boxed: return "boxed";
        case PatternKind::Bozo: return "bozo";
        case PatternKind::Bumps: return "bumps";
        case PatternKind::Cells: return "cells";
        case PatternKind::Crackle: return "crackle";
        case PatternKind::Cylindrical: return "cylindrical";
        case PatternKind::Dents: return "dents";
        case PatternKind::Facets: return "facets";
        case PatternKind::Granite: return "granite";
        case PatternKind::Leopard: return "leopard";
        case PatternKind::Marble: return "marble";
        case PatternKind::Onion: return "onion";
        case PatternKind::Planar: return "planar";
        case PatternKind::Quilted: return "quilted";
        case PatternKind::Radial: return "radial";
        case PatternKind::Ripples: return "ripples";
        case PatternKind::Spherical: return "spherical";
        case PatternKind::Spiral1: return "spiral1";
        case PatternKind::Spiral2: return "spiral2";
        case PatternKind::Spotted: return "spotted";
        case PatternKind::Waves: return "waves";
        case PatternKind::Wood: return "wood";
        case PatternKind::Wrinkles: return "wrinkles";
        case PatternKind::Mandel: return "mandel";
        case PatternKind::Julia: return "julia";
        case PatternKind::Magnet: return "magnet";
        case PatternKind::Tiling: return "tiling";
        case PatternKind::ImagePattern: return "image_pattern";
        case PatternKind::Function: return "function";
        case PatternKind::DensityFile: return "density_file";
        case PatternKind::Brick: return "brick";
        case PatternKind::Hexagon: return "hexagon";
        case PatternKind::Square: return "square";
        case PatternKind::Triangular: return "triangular";
        case PatternKind::Cubic: return "cubic";
        case PatternKind::Object: return "object";
        case PatternKind::PigmentPattern: return "pigment_pattern";
        case PatternKind::Slope: return "slope";
        case PatternKind::Aoi: return "aoi";
        case PatternKind::Average: return "average";
    }
    return "?";
}

}  // namespace glint::scene
