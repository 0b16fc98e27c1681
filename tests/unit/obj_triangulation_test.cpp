// How OBJ faces become triangles (formats/obj/face_triangulation.h): Blender's cut of quads,
// which Cycles renders, and ear clipping of larger polygons.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "formats/obj/face_triangulation.h"
#include "formats/obj/obj_importer.h"

namespace glint::obj {
namespace {

using Tris = std::vector<std::array<int, 3>>;

Tris cut(const std::vector<Vec3>& c) {
    Tris t;
    triangulate_face(c, &t);
    return t;
}

// Twice the signed area of triangle abc seen along `n`.
double signed_area(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
    return dot(cross(b - a, c - a), n);
}

TEST(ObjTriangulation, TriangleStaysAsItIs) {
    EXPECT_EQ(cut({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), (Tris{{0, 1, 2}}));
}

TEST(ObjTriangulation, QuadsAreCutOnTheirFirstDiagonal) {
    // A square and an isosceles trapezoid have diagonals of equal length (tinyobjloader's
    // shorter-diagonal rule then picks 1-3); a kite whose 0-2 diagonal is the longer one
    // (tinyobjloader: 1-3). Blender cuts all three on 0-2.
    EXPECT_EQ(cut({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}), (Tris{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(cut({{0, 0, 0}, {3, 0, 0}, {2, 1, 0}, {1, 1, 0}}), (Tris{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(cut({{0, 0, 0}, {2, -0.5, 0}, {4, 0, 0}, {2, 0.5, 0}}), (Tris{{0, 1, 2}, {0, 2, 3}}));
}

TEST(ObjTriangulation, ConcaveQuadIsCutOnTheDiagonalInside) {
    // Corner 1 is pushed in past the 0-2 diagonal (a dart): 0-2 runs outside, so 1-3.
    const std::vector<Vec3> dart{{0, 0, 0}, {1, 1.5, 0}, {2, 0, 0}, {1, 3, 0}};
    const Tris t = cut(dart);
    EXPECT_EQ(t, (Tris{{0, 1, 3}, {1, 2, 3}}));
    for (const auto& tri : t)
        EXPECT_GT(signed_area(dart[tri[0]], dart[tri[1]], dart[tri[2]], Vec3(0, 0, 1)), 0);
}

TEST(ObjTriangulation, ConvexPolygonBecomesAFanAroundCornerZero) {
    std::vector<Vec3> hexagon;
    for (int i = 0; i < 6; ++i)
        hexagon.emplace_back(std::cos(i * kPi / 3), 0.25, std::sin(i * kPi / 3));
    EXPECT_EQ(cut(hexagon), (Tris{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}));
}

TEST(ObjTriangulation, ConcavePolygonIsCoveredWithoutOverlap) {
    // An L of six corners (area 3) in a tilted plane, wound counter-clockwise about n.
    const Vec3 u = normalize(Vec3(1, 0.3, 0)), v = normalize(cross(Vec3(0.2, 0.1, 1), u));
    const Vec3 n = cross(u, v);
    const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    for (int start = 0; start < 6; ++start) {  // every corner first, the reflex one included
        std::vector<Vec3> poly;
        for (int k = 0; k < 6; ++k) {
            const double* p = xy[(start + k) % 6];
            poly.push_back(u * p[0] + v * p[1] + Vec3(5, -2, 7));
        }
        const Tris t = cut(poly);
        ASSERT_EQ(t.size(), 4u) << "start " << start;
        double area = 0;
        for (const auto& tri : t) {
            const double a = signed_area(poly[tri[0]], poly[tri[1]], poly[tri[2]], n);
            EXPECT_GT(a, 0) << "start " << start;  // same winding, none folded over
            area += a / 2;
        }
        EXPECT_NEAR(area, 3.0, 1e-12) << "start " << start;  // covered exactly once
    }
}

TEST(ObjTriangulation, PolygonWithoutAreaIsAFan) {
    EXPECT_EQ(cut({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}),
              (Tris{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

TEST(ObjTriangulation, ImporterCutsSmoothQuadsAsBlenderDoes) {
    // A bent quad (corner 2 raised) with a distinct normal per corner: which diagonal the cut
    // takes decides every interpolated normal inside it.
    namespace fs = std::filesystem;
    const fs::path path = fs::temp_directory_path() /
                          ("glint-obj-triangulation-" + std::to_string(::getpid()) + ".obj");
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\n"
                           "vn 0 0 1\nvn 0.1 0 1\nvn 0.1 0.1 1\nvn 0 0.1 1\n"
                           "f 1//1 2//2 3//3 4//4\n";
    scene::Scene s;
    Diagnostics diag;
    import_obj(path.string(), s, Transform{}, -1, diag);
    fs::remove(path);
    ASSERT_EQ(s.meshes.size(), 1u);
    const scene::Mesh& m = s.meshes[0];
    ASSERT_EQ(m.faces.size(), 2u);
    auto corner = [&](int f, int k) { return m.positions[m.faces[f].v[k]]; };
    auto normal = [&](int f, int k) { return m.normals[m.faces[f].n[k]]; };
    // (0 1 2) and (0 2 3): both triangles hold corners 0 and 2 of the quad.
    for (int f = 0; f < 2; ++f) {
        EXPECT_EQ(corner(f, 0), Vec3(0, 0, 0));
        EXPECT_EQ(normal(f, 0), Vec3(0, 0, 1));
    }
    EXPECT_EQ(corner(0, 2), Vec3(1, 1, 0.5));
    EXPECT_EQ(corner(1, 1), Vec3(1, 1, 0.5));
    EXPECT_EQ(normal(1, 2), Vec3(0, 0.1, 1));
}

}  // namespace
}  // namespace glint::obj
