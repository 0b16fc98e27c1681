// OBJ loading: glint's importer (tinyobjloader + conversion into the IR) against
// tinyobjloader's parse alone, on the same file. The ratio is the importer's overhead.
//   GLINT_OBJ=/path/mesh.obj build-bench/bench/obj_load_bench --benchmark_repetitions=5
// Without GLINT_OBJ a 1M-triangle bumpy sphere is written to the temp folder first.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <tiny_obj_loader.h>

#include "formats/obj/obj_importer.h"

namespace {

std::string obj_path() {
    if (const char* p = std::getenv("GLINT_OBJ")) return p;
    static std::string path;
    if (!path.empty()) return path;
    path = (std::filesystem::temp_directory_path() / "glint_bench_1m.obj").string();
    if (std::filesystem::exists(path)) return path;
    // A latitude/longitude sphere of 2 * 500 * 1000 = 1M triangles with normals.
    const int nu = 1000, nv = 500;
    std::ofstream out(path);
    char buf[160];
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            double th = M_PI * j / nv, ph = 2 * M_PI * i / nu;
            double r = 1 + 0.02 * std::sin(7 * ph) * std::sin(5 * th);
            double x = std::sin(th) * std::cos(ph), y = std::cos(th), z = std::sin(th) * std::sin(ph);
            std::snprintf(buf, sizeof buf, "v %.6f %.6f %.6f\nvn %.6f %.6f %.6f\n", r * x, r * y,
                          r * z, x, y, z);
            out << buf;
        }
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            int a = j * (nu + 1) + i + 1, b = a + 1, c = a + nu + 1, d = c + 1;
            std::snprintf(buf, sizeof buf, "f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n", a,
                          a, c, c, d, d, a, a, d, d, b, b);
            out << buf;
        }
    return path;
}

void BM_TinyObjParseOnly(benchmark::State& state) {
    const std::string path = obj_path();
    for (auto _ : state) {
        tinyobj::ObjReaderConfig config;
        config.triangulate = true;
        config.vertex_color = false;
        tinyobj::ObjReader reader;
        if (!reader.ParseFromFile(path, config)) state.SkipWithError("parse failed");
        benchmark::DoNotOptimize(reader.GetShapes().data());
    }
}

void BM_GlintImportObj(benchmark::State& state) {
    const std::string path = obj_path();
    long long tris = 0;
    for (auto _ : state) {
        glint::scene::Scene scene;
        glint::Diagnostics diag;
        tris = glint::obj::import_obj(path, scene, glint::Transform{}, -1, diag).triangles;
        benchmark::DoNotOptimize(scene.meshes.data());
    }
    state.counters["triangles"] = static_cast<double>(tris);
}

BENCHMARK(BM_TinyObjParseOnly)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GlintImportObj)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
