// The grids of a Blender Volume object: an OpenVDB file read once per render, for scenes that
// have such objects only (a scene without one never opens OpenVDB). Sampled as Cycles 3.4
// samples them: trilinearly between voxel centres, each voxel centred half a voxel above its
// index as Cycles places it, zero outside the grid; the file's space is the object's, its
// transform taking it into the world.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "core/log.h"
#include "core/transform.h"
#include "render/shader/closures.h"

namespace glint::render {

class VdbGrids final : public shader::VolumeGridSource {
public:
    // Reads every float, double and vector grid of `path`; a file that cannot be read (or
    // holds none of those) is warned about with `loc` and samples as no grid at all.
    VdbGrids(const std::string& path, const Transform& object_to_world, Diagnostics& diag,
             const FileLoc& loc);
    ~VdbGrids() override;

    bool grid(std::string_view name, const Vec3& p, Vec3* value) const override;
    int count() const;
    // Cycles' automatic step: the voxel's edge vector taken into the world, its smallest
    // component (over the grids, the smallest); 0 without grids.
    double voxel_step() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace glint::render
