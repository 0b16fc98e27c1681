#include "render/textures/vdb_grids.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/Interpolation.h>

namespace glint::render {
namespace {

// Grids up to this many voxels (in their active bounds) are copied into a dense array, read
// directly by the trilinear lookup: a smoke cache of 256^3 is 64 MiB per grid. Tree lookups,
// even through an accessor, took half the time of a volume render.
constexpr uint64_t kDenseMax = uint64_t{1} << 24;

// One grid of the file.
struct Grid {
    std::string name;
    int channels = 1;
    // Sparse: the tree (grids past kDenseMax, and transforms that are not affine).
    openvdb::FloatGrid::ConstPtr scalar;
    openvdb::Vec3SGrid::ConstPtr vector;
    openvdb::math::Transform::ConstPtr xform;
    // Dense: values over [lo, lo + dim), x slowest, then y, z, `channels` per voxel;
    // `background` outside.
    std::vector<float> dense;
    int lo[3] = {0, 0, 0}, dim[3] = {0, 0, 0};
    float background[3] = {0, 0, 0};
    Matrix4 world_to_index;  // with Cycles' half-voxel shift folded in

    // The value at integer index (x, y, z) of the dense copy.
    void fetch(int x, int y, int z, float* out) const {
        const int ix = x - lo[0], iy = y - lo[1], iz = z - lo[2];
        if (ix < 0 || iy < 0 || iz < 0 || ix >= dim[0] || iy >= dim[1] || iz >= dim[2]) {
            for (int c = 0; c < channels; ++c) out[c] = background[c];
            return;
        }
        const size_t at = ((static_cast<size_t>(ix) * dim[1] + iy) * dim[2] + iz) * channels;
        for (int c = 0; c < channels; ++c) out[c] = dense[at + c];
    }
};

}  // namespace

struct VdbGrids::Impl {
    std::vector<Grid> grids;
    Transform to_world;
};

namespace {

template <class GridT>
void make_dense(const GridT& grid, Grid* g, int channels) {
    using Value = typename GridT::ValueType;
    const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    if (box.empty()) return;
    const openvdb::Coord d = box.dim();
    const uint64_t count = uint64_t(d.x()) * uint64_t(d.y()) * uint64_t(d.z());
    if (count > kDenseMax) return;
    openvdb::tools::Dense<Value, openvdb::tools::LayoutZYX> dense(box);
    openvdb::tools::copyToDense(grid, dense);
    g->channels = channels;
    for (int k = 0; k < 3; ++k) {
        g->lo[k] = box.min()[k];
        g->dim[k] = d[k];
    }
    g->dense.resize(count * static_cast<size_t>(channels));
    const Value* src = dense.data();
    for (uint64_t i = 0; i < count; ++i) {
        if constexpr (std::is_same_v<Value, float>) {
            g->dense[i] = src[i];
        } else {
            for (int c = 0; c < 3; ++c) g->dense[i * 3 + c] = src[i][c];
        }
    }
    const Value bg = grid.background();
    if constexpr (std::is_same_v<Value, float>) {
        g->background[0] = bg;
    } else {
        for (int c = 0; c < 3; ++c) g->background[c] = bg[c];
    }
}

}  // namespace

VdbGrids::VdbGrids(const std::string& path, const Transform& object_to_world, Diagnostics& diag,
                   const FileLoc& loc)
    : impl_(std::make_unique<Impl>()) {
    impl_->to_world = object_to_world;
    static std::once_flag init;
    std::call_once(init, [] { openvdb::initialize(); });
    try {
        openvdb::io::File file(path);
        file.open();
        for (auto it = file.beginName(); it != file.endName(); ++it) {
            openvdb::GridBase::Ptr base = file.readGrid(it.gridName());
            Grid g;
            g.name = it.gridName();
            g.xform = base->transformPtr();
            if (auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(base)) {
                g.scalar = f;
            } else if (auto d = openvdb::gridPtrCast<openvdb::DoubleGrid>(base)) {
                // Doubles as floats (Cycles keeps single precision too).
                auto copy = openvdb::FloatGrid::create(static_cast<float>(d->background()));
                copy->setTransform(d->transform().copy());
                auto acc = copy->getAccessor();
                for (auto v = d->cbeginValueOn(); v; ++v)
                    acc.setValue(v.getCoord(), static_cast<float>(*v));
                g.scalar = copy;
            } else if (auto v3 = openvdb::gridPtrCast<openvdb::Vec3SGrid>(base)) {
                g.vector = v3;
                g.channels = 3;
            } else {
                diag.warning(loc, "volume file '" + path + "': grid '" + g.name + "' of type " +
                                      base->valueType() + " is not read");
                continue;
            }
            // Index = the grid's inverse map of the object point, less Cycles' half voxel.
            if (g.xform->isLinear()) {
                const openvdb::math::Mat4d m =
                    g.xform->baseMap()->getAffineMap()->getMat4().inverse();
                Matrix4 w2i;
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c) w2i.m[r][c] = m[c][r];  // OpenVDB: row vectors
                for (int r = 0; r < 3; ++r) w2i.m[r][3] -= 0.5;
                g.world_to_index = w2i * object_to_world.inverse_matrix();
                if (g.scalar) make_dense(*g.scalar, &g, 1);
                else make_dense(*g.vector, &g, 3);
            }
            impl_->grids.push_back(std::move(g));
        }
        file.close();
    } catch (const std::exception& e) {
        diag.warning(loc, "volume file '" + path + "' cannot be read: " + e.what() +
                              " (the volume renders empty)");
        impl_->grids.clear();
    }
}

VdbGrids::~VdbGrids() = default;

int VdbGrids::count() const { return static_cast<int>(impl_->grids.size()); }

bool VdbGrids::grid(std::string_view name, const Vec3& p, Vec3* value) const {
    for (const Grid& g : impl_->grids) {
        if (g.name != name) continue;
        if (!g.dense.empty()) {
            // Trilinear between the eight voxels around the point.
            const Matrix4& m = g.world_to_index;
            double q[3];
            for (int r = 0; r < 3; ++r)
                q[r] = m.m[r][0] * p.x + m.m[r][1] * p.y + m.m[r][2] * p.z + m.m[r][3];
            const double fx = std::floor(q[0]), fy = std::floor(q[1]), fz = std::floor(q[2]);
            const int x = static_cast<int>(std::clamp(fx, -2e9, 2e9));
            const int y = static_cast<int>(std::clamp(fy, -2e9, 2e9));
            const int z = static_cast<int>(std::clamp(fz, -2e9, 2e9));
            const double tx = q[0] - fx, ty = q[1] - fy, tz = q[2] - fz;
            const int ix = x - g.lo[0], iy = y - g.lo[1], iz = z - g.lo[2];
            if (g.channels == 1 && ix >= 0 && iy >= 0 && iz >= 0 && ix + 1 < g.dim[0] &&
                iy + 1 < g.dim[1] && iz + 1 < g.dim[2]) {
                // All eight inside the dense copy (most lookups): straight from the array.
                const size_t sy = static_cast<size_t>(g.dim[2]);
                const size_t sx = sy * static_cast<size_t>(g.dim[1]);
                const float* c = g.dense.data() + static_cast<size_t>(ix) * sx +
                                 static_cast<size_t>(iy) * sy + static_cast<size_t>(iz);
                auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
                const double v = lerp(lerp(lerp(c[0], c[1], tz), lerp(c[sy], c[sy + 1], tz), ty),
                                      lerp(lerp(c[sx], c[sx + 1], tz),
                                           lerp(c[sx + sy], c[sx + sy + 1], tz), ty),
                                      tx);
                *value = Vec3(v, v, v);
                return true;
            }
            double acc[3] = {0, 0, 0};
            for (int corner = 0; corner < 8; ++corner) {
                const int dx = corner >> 2, dy = (corner >> 1) & 1, dz = corner & 1;
                const double w = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty) * (dz ? tz : 1 - tz);
                float v[3];
                g.fetch(x + dx, y + dy, z + dz, v);
                for (int c = 0; c < g.channels; ++c) acc[c] += w * v[c];
            }
            *value = g.channels == 1 ? Vec3(acc[0], acc[0], acc[0]) : Vec3(acc[0], acc[1], acc[2]);
            return true;
        }
        // Cycles takes voxel (i, j, k) to fill the cell from i to i + 1 (its texture texels'
        // centres), not to sit at i as OpenVDB does: its value is found half a voxel up.
        const Vec3 o = impl_->to_world.inverse_point(p);
        const openvdb::Vec3d ijk =
            g.xform->worldToIndex(openvdb::Vec3d(o.x, o.y, o.z)) - openvdb::Vec3d(0.5);
        // A fresh accessor per sample (they are not shared between threads): its cache
        // serves the eight corners, which mostly share a leaf.
        if (g.scalar) {
            float v = 0;
            const auto acc = g.scalar->getConstUnsafeAccessor();
            openvdb::tools::BoxSampler::sample(acc, ijk, v);
            *value = Vec3(v, v, v);
        } else {
            openvdb::Vec3s v(0, 0, 0);
            const auto acc = g.vector->getConstUnsafeAccessor();
            openvdb::tools::BoxSampler::sample(acc, ijk, v);
            *value = Vec3(v[0], v[1], v[2]);
        }
        return true;
    }
    return false;
}

double VdbGrids::voxel_step() const {
    double step = 0;
    for (const Grid& g : impl_->grids) {
        const openvdb::Vec3d vs = g.xform->voxelSize();
        const Vec3 w = impl_->to_world.vector(Vec3(vs[0], vs[1], vs[2]));
        const double s = std::min({std::fabs(w.x), std::fabs(w.y), std::fabs(w.z)});
        if (s > 0 && (step == 0 || s < step)) step = s;
    }
    return step;
}

}  // namespace glint::render
