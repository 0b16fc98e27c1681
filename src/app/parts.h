// Renders split into parts (`glint render --region`, `--frames`, `glint merge`, `glint farm`):
// how a region is written and read, how an image is cut into tiles, and the metadata every
// part carries so that a merge can tell its parts belong together. One header for the three
// commands that must agree on it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/image_output.h"
#include "render/render.h"

namespace glint::app {

// `x0,y0,x1,y1`: the pixels [x0, x1) x [y0, y1), 0-based, row 0 at the top. Throws
// Error(Usage) naming `flag` for anything else.
render::Region parse_region(const std::string& text, const std::string& flag);
std::string region_string(const render::Region& r);

// `A-B` (or `A`): an inclusive range of frame numbers. Throws Error(Usage) naming `flag`.
struct FrameRange {
    int first = 1, last = 1;
};
FrameRange parse_frame_range(const std::string& text, const std::string& flag);

// About `n` rectangles covering a width x height image, in rows and columns chosen to keep
// them near square, their edges on the 32-pixel blocks of the render driver where the image
// has enough of them (adaptive anti-aliasing then traces no pixel twice). Row by row, top
// first. Throws Error(Usage) when n < 1 or the image has fewer pixels than n.
std::vector<render::Region> split_into_tiles(int width, int height, int n);

// The metadata keys of a part, in the file's header (PNG text, EXR attributes).
inline constexpr const char* kJobKey = "glint:job";          // job_signature()
inline constexpr const char* kRegionKey = "glint:region";    // region_string()
inline constexpr const char* kSizeKey = "glint:image_size";  // "WxH" of the whole image
inline constexpr const char* kFrameKey = "glint:frame";      // frame number of an animation

// A 64-bit FNV-1a hash, for job signatures.
uint64_t fnv1a(const void* data, size_t size, uint64_t h = 0xcbf29ce484222325ull);
// The job a part belongs to, as 16 hex digits: a hash of `settings` (every setting that
// changes pixels: the render command builds it) and of the bytes of the scene file. Parts
// of one image or frames of one animation share it; anything else almost surely does not.
std::string job_signature(const std::string& settings, const std::string& scene_path);

}  // namespace glint::app
