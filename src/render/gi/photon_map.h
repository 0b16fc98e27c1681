// POV-Ray 3.7's surface photon map (backend/lighting/photons.cpp): photons stored where light
// that came through or off a target object lands, a kd-tree over them, the nearest-photons
// gather with POV-Ray's "flattened" distance (photons off the surface's plane count as
// farther), the adaptive gather radius (expand_thresholds) and the radius POV-Ray estimates
// from the map's own density when the scene gives none.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "scene/color.h"
#include "scene/scene.h"

namespace glint::render {

struct Photon {
    Vec3 p;
    Vec3 to_source;  // unit: back along the path the light came in on
    Color power;     // POV-Ray's photon colour: light times spread^2 times path length^2
};

// The photons of one gather, nearest first is not promised; `radius` is the disc they were
// counted over (the search radius, or the farthest photon's distance once `gather` max were
// found).
struct PhotonGather {
    std::vector<const Photon*> photons;
    double radius = 0;
};

// Photons in a file (photons { save_file / load_file }): glint's own binary format (POV-Ray's
// is its own too), the surface and media photons in the order they were shot, so a loaded
// map is the map that was saved. Written to a temporary name and renamed. Errors name the
// file and the photons block `at`.
void write_photon_file(const std::string& path, const std::vector<Photon>& surface,
                       const std::vector<Photon>& media, const FileLoc& at);
void read_photon_file(const std::string& path, std::vector<Photon>* surface,
                      std::vector<Photon>* media, const FileLoc& at);

class PhotonMap {
public:
    // Takes the photons (in a fixed order, so the tree and every gather are the same whatever
    // the thread count), builds the tree and sets the gather radius (settings' radius, or
    // estimated from the density with a fixed-seed choice of sample photons). `volume`: a
    // media photon map (densities per volume, the media radius settings, the radius doubled).
    PhotonMap(std::vector<Photon> photons, const scene::Photons& settings, bool volume = false);

    size_t size() const { return photons_.size(); }
    double gather_radius() const { return radius_; }

    // PhotonGatherer::gatherPhotonsAdaptive at `p` on a surface with normal `n` (null in a
    // medium): the nearest photons (at most gather max) within the radius, widened in steps
    // while fewer than gather min were found and the density holds (expand_thresholds).
    void gather(const Vec3& p, const Vec3* n, PhotonGather* out) const;

private:
    // gatherPhotons: up to `max_count` nearest within `size`; returns the radius counted over.
    double nearest(const Vec3& p, double size, const Vec3* n, int max_count,
                   std::vector<std::pair<double, uint32_t>>* heap) const;
    void build(uint32_t lo, uint32_t hi);
    void estimate_radius();
    double density(size_t count, double r) const;  // photons per area (volume) within r

    std::vector<Photon> photons_;  // in kd-tree order (median of each range at its middle)
    std::vector<uint8_t> axis_;    // split axis of each range's median
    scene::Photons settings_;
    bool volume_ = false;
    double radius_ = 0;
    double radius_step_ = 0;
};

}  // namespace glint::render
