// The OpenVDB grids of Blender Volume objects (render/textures/vdb_grids.h): values where
// Cycles 3.4 finds them (each voxel centred half a voxel above its index), trilinear between
// voxels, through the object's transform, zero outside; vector grids; the automatic step is
// the voxel in the world; a missing file is a warning and no grids.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <openvdb/openvdb.h>

#include "core/log.h"
#include "render/textures/vdb_grids.h"

namespace glint {
namespace {

using render::VdbGrids;

// A file with 'ramp' (value = x index over 0..15 x 0..3 x 0..3) and 'wind' (a vector grid
// (1, 2, 3) at every voxel of 0..3^3), voxels of `voxel`. Each test writes its own file:
// ctest runs the tests of this file side by side, and one would read the other's half-written
// file.
std::string write_file(double voxel) {
    openvdb::initialize();
    auto ramp = openvdb::FloatGrid::create(0.0f);
    ramp->setName("ramp");
    auto wind = openvdb::Vec3SGrid::create(openvdb::Vec3s(0, 0, 0));
    wind->setName("wind");
    auto a = ramp->getAccessor();
    auto w = wind->getAccessor();
    for (int x = 0; x < 16; ++x)
        for (int y = 0; y < 4; ++y)
            for (int z = 0; z < 4; ++z) {
                a.setValue(openvdb::Coord(x, y, z), static_cast<float>(x));
                if (x < 4) w.setValue(openvdb::Coord(x, y, z), openvdb::Vec3s(1, 2, 3));
            }
    const auto xf = openvdb::math::Transform::createLinearTransform(voxel);
    ramp->setTransform(xf);
    wind->setTransform(xf->copy());
    const std::string path =
        (std::filesystem::temp_directory_path() /
         ("glint_vdb_grids_" + std::to_string(::getpid()) + "_" +
          ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".vdb"))
            .string();
    openvdb::io::File(path).write({ramp, wind});
    return path;
}

TEST(VdbGrids, ValuesWhereCyclesFindsThem) {
    const double vs = 0.1;
    Diagnostics diag;
    VdbGrids g(write_file(vs), Transform(), diag, FileLoc{});
    ASSERT_EQ(g.count(), 2);
    Vec3 v;
    // Voxel 5's value sits at x = (5 + 0.5) voxel; between 5 and 6 it is linear.
    ASSERT_TRUE(g.grid("ramp", Vec3(5.5 * vs, 1.5 * vs, 1.5 * vs), &v));
    EXPECT_NEAR(v.x, 5, 1e-5);
    EXPECT_NEAR(v.y, 5, 1e-5);  // a scalar grid in every channel
    ASSERT_TRUE(g.grid("ramp", Vec3(5.75 * vs, 1.5 * vs, 1.5 * vs), &v));
    EXPECT_NEAR(v.x, 5.25, 1e-5);
    // Outside the grid: the background (0).
    ASSERT_TRUE(g.grid("ramp", Vec3(-3.0, 0, 0), &v));
    EXPECT_EQ(v.x, 0);
    ASSERT_TRUE(g.grid("wind", Vec3(1.5 * vs, 1.5 * vs, 1.5 * vs), &v));
    EXPECT_NEAR(v.x, 1, 1e-6);
    EXPECT_NEAR(v.y, 2, 1e-6);
    EXPECT_NEAR(v.z, 3, 1e-6);
    EXPECT_FALSE(g.grid("density", Vec3(), &v));
    EXPECT_NEAR(g.voxel_step(), vs, 1e-12);
}

TEST(VdbGrids, FollowTheObjectTransform) {
    const double vs = 0.1;
    Diagnostics diag;
    // Scaled by 2, then moved by (1, 2, 3): voxel 5 of the ramp is at x = 1 + 2 * 0.55.
    const Transform t = Transform::scale(Vec3(2, 2, 2)).then(Transform::translate(Vec3(1, 2, 3)));
    VdbGrids g(write_file(vs), t, diag, FileLoc{});
    Vec3 v;
    ASSERT_TRUE(g.grid("ramp", Vec3(1 + 2 * 5.5 * vs, 2 + 2 * 1.5 * vs, 3 + 2 * 1.5 * vs), &v));
    EXPECT_NEAR(v.x, 5, 1e-5);
    EXPECT_NEAR(g.voxel_step(), 2 * vs, 1e-12);
}

TEST(VdbGrids, MissingFileWarnsAndHasNoGrids) {
    Diagnostics diag;
    VdbGrids g("/nonexistent/smoke.vdb", Transform(), diag, FileLoc{});
    EXPECT_EQ(g.count(), 0);
    Vec3 v;
    EXPECT_FALSE(g.grid("density", Vec3(), &v));
    ASSERT_EQ(diag.warning_count(), 1);
    EXPECT_NE(diag.all()[0].message.find("cannot be read"), std::string::npos);
}

}  // namespace
}  // namespace glint
