// The colour table of a palette (colour-mapped) image, for what POV-Ray does with the indices:
// height fields take their heights from them, and image maps' `filter N, V` / `transmit N, V`
// edit one entry. The image readers expand palettes to colours; the index of a pixel is found
// back from its colour.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace glint {

using PaletteColor = std::array<uint8_t, 3>;

// The colour table of a palette image (PNG colour type 3, GIF's global table); empty for other
// files and for files that cannot be read.
std::vector<PaletteColor> read_palette(const std::string& path);

// The index of an expanded pixel (`channels` values in [0, 1], grey replicated): the first
// entry with its colour, or the red value when no entry has it.
int palette_index(const std::vector<PaletteColor>& palette, const float* pixel, int channels);

}  // namespace glint
