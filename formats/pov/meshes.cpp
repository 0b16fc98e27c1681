// Meshes (reference manual 3.4.2.6 "Mesh" and 3.4.2.7 "Mesh2"; parse.cpp Parse_Mesh,
// Parse_Mesh2): triangle lists with per-vertex normals and uvs and per-face textures, counted
// against --max-triangles.
#include "formats/pov/literal_list.h"
#include "formats/pov/object_bodies.h"
#include "formats/pov/solids.h"

namespace glint::pov {
namespace {

void parse_mesh_triangle(Parser& p, scene::Mesh& mesh, bool smooth) {
    p.expect_open(smooth ? "smooth_triangle" : "triangle");
    FileLoc o = p.loc();
    scene::MeshFace f;
    for (int i = 0; i < 3; ++i) {
        if (i > 0) p.skip_comma();
        f.v[i] = static_cast<int>(mesh.positions.size());
        mesh.positions.push_back(p.parse_vector());
        if (smooth) {
            p.skip_comma();
            f.n[i] = static_cast<int>(mesh.normals.size());
            mesh.normals.push_back(p.parse_vector());
        }
    }
    for (;;) {
        if (p.accept("uv_vectors")) {
            for (int i = 0; i < 3; ++i) {
                if (i > 0) p.skip_comma();
                Num n = p.parse_num(2);
                f.uv[i] = static_cast<int>(mesh.uvs.size());
                mesh.uvs.push_back({n.v[0], n.v[1]});
            }
        } else if (p.accept("texture")) {
            p.expect_open("texture");
            FileLoc to = p.loc();
            scene::Texture t = p.parse_texture_body();
            p.expect_close("texture", to);
            f.material = p.add_material(t, scene::Interior{}, to);
        } else {
            break;
        }
    }
    p.expect_close(smooth ? "smooth_triangle" : "triangle", o);
    mesh.faces.push_back(f);
}

// mesh2 sections: `name { count, item, item, ... }`. A list written as literal vectors of
// `dims` numbers (literal_list.h) is checked by ok(list) and, if it passes and the token limit
// allows, given to take(list) whole. Otherwise its items are read one by one, as if the fast
// path did not exist, and say what is wrong with them.
template <typename F, typename Ok, typename Take>
void parse_counted(Parser& p, const char* name, F item, int dims, Ok ok, Take take) {
    p.expect_open(name);
    FileLoc o = p.loc();
    if (const Token* list = dims > 0 ? p.take_number_list() : nullptr) {
        LiteralList l;
        if (read_literal_list(list->text, dims, &l) && ok(l) && p.count_tokens(l.tokens, p.loc())) {
            take(l);
            p.expect_close(name, o);
            return;
        }
        p.give_back_number_list(*list);
    }
    int n = to_int(p.parse_float());
    if (n < 0) p.fail(std::string("negative count in ") + name);
    for (int i = 0; i < n; ++i) {
        p.skip_comma();
        item(i);
    }
    p.skip_comma();  // POV-Ray accepts a comma after the last item
    p.expect_close(name, o);
}

template <typename F>
void parse_counted(Parser& p, const char* name, F item) {
    auto none = [](const LiteralList&) { return false; };
    parse_counted(p, name, item, 0, none, none);
}

// The fast path's checks and copies (parse_counted): indices as idx3 would take them, or not
// at all (then idx3 says which is out of range, and where).
bool in_range(const LiteralList& l, int limit) {
    for (double v : l.values) {
        const int r = to_int(v);
        if (r < 0 || r >= limit) return false;
    }
    return true;
}

void append_vectors(const LiteralList& l, std::vector<Vec3>* out) {
    out->reserve(out->size() + l.values.size() / 3);
    for (size_t k = 0; k + 2 < l.values.size(); k += 3)
        out->push_back(Vec3(l.values[k], l.values[k + 1], l.values[k + 2]));
}

void parse_mesh2(Parser& p, scene::Mesh& mesh) {
    auto any_list = [](const LiteralList&) { return true; };
    std::vector<int> textures;
    auto idx3 = [&](const char* what, int limit) {
        p.peek();
        FileLoc at = p.loc();
        Vec3 v = p.parse_vector();
        std::array<int, 3> r{to_int(v.x), to_int(v.y), to_int(v.z)};
        for (int k = 0; k < 3; ++k)
            if (r[k] < 0 || r[k] >= limit) {
                // The value as written: 2e72 clamped to int would read as 2147483647.
                char shown[32];
                std::snprintf(shown, sizeof shown, "%.10g", v[k]);
                p.fail_at(at, std::string(what) + " index " + shown + " is out of range (0.." +
                                  std::to_string(limit - 1) + ")");
            }
        return r;
    };
    for (;;) {
        if (p.accept("vertex_vectors")) {
            parse_counted(p, "vertex_vectors", [&](int) { mesh.positions.push_back(p.parse_vector()); },
                          3, any_list, [&](const LiteralList& l) { append_vectors(l, &mesh.positions); });
        } else if (p.accept("normal_vectors")) {
            parse_counted(p, "normal_vectors", [&](int) { mesh.normals.push_back(p.parse_vector()); },
                          3, any_list, [&](const LiteralList& l) { append_vectors(l, &mesh.normals); });
        } else if (p.accept("uv_vectors")) {
            parse_counted(p, "uv_vectors", [&](int) {
                Num n = p.parse_num(2);
                mesh.uvs.push_back({n.v[0], n.v[1]});
            }, 2, any_list, [&](const LiteralList& l) {
                for (size_t k = 0; k + 1 < l.values.size(); k += 2)
                    mesh.uvs.push_back({l.values[k], l.values[k + 1]});
            });
        } else if (p.accept("texture_list")) {
            parse_counted(p, "texture_list", [&](int) {
                p.expect("texture", "in texture_list");
                p.expect_open("texture");
                FileLoc to = p.loc();
                scene::Texture t = p.parse_texture_body();
                p.expect_close("texture", to);
                textures.push_back(p.add_material(t, scene::Interior{}, to));
            });
        } else if (p.accept("face_indices")) {
            int nv = static_cast<int>(mesh.positions.size());
            // With a texture_list a face may name textures after its vector: token by token.
            auto faces_ok = [&](const LiteralList& l) { return textures.empty() && in_range(l, nv); };
            auto take_faces = [&](const LiteralList& l) {
                for (size_t k = 0; k + 2 < l.values.size(); k += 3) {
                    scene::MeshFace f;
                    f.v = {to_int(l.values[k]), to_int(l.values[k + 1]), to_int(l.values[k + 2])};
                    mesh.faces.push_back(f);
                }
            };
            parse_counted(p, "face_indices", [&](int) {
                scene::MeshFace f;
                f.v = idx3("vertex", nv);
                if (p.peek().is(",") && !textures.empty()) {
                    p.skip_comma();
                    if (p.next_is_expression_start() && p.peek().kind != TokKind::Symbol) {
                        int t = to_int(p.parse_float());
                        if (t < 0 || t >= static_cast<int>(textures.size()))
                            p.fail("texture index out of range");
                        f.material = textures[t];
                        if (p.accept(",")) {
                            if (p.peek().kind == TokKind::Number) {
                                p.parse_float();  // per-vertex textures: the first one is used
                                p.skip_comma();
                                p.parse_float();
                            } else {
                                p.unget();
                            }
                        }
                    }
                }
                mesh.faces.push_back(f);
            }, 3, faces_ok, take_faces);
        } else if (p.accept("normal_indices")) {
            int nn = static_cast<int>(mesh.normals.size());
            size_t i = 0;
            parse_counted(p, "normal_indices", [&](int) {
                auto r = idx3("normal", nn);
                if (i < mesh.faces.size()) mesh.faces[i].n = r;
                ++i;
            }, 3, [&](const LiteralList& l) { return in_range(l, nn); },
               [&](const LiteralList& l) {
                for (size_t k = 0; k + 2 < l.values.size(); k += 3, ++i)
                    if (i < mesh.faces.size())
                        mesh.faces[i].n = {to_int(l.values[k]), to_int(l.values[k + 1]),
                                           to_int(l.values[k + 2])};
            });
        } else if (p.accept("uv_indices")) {
            int nu = static_cast<int>(mesh.uvs.size());
            size_t i = 0;
            parse_counted(p, "uv_indices", [&](int) {
                auto r = idx3("uv", nu);
                if (i < mesh.faces.size()) mesh.faces[i].uv = r;
                ++i;
            }, 3, [&](const LiteralList& l) { return in_range(l, nu); },
               [&](const LiteralList& l) {
                for (size_t k = 0; k + 2 < l.values.size(); k += 3, ++i)
                    if (i < mesh.faces.size())
                        mesh.faces[i].uv = {to_int(l.values[k]), to_int(l.values[k + 1]),
                                            to_int(l.values[k + 2])};
            });
        } else {
            break;
        }
    }
    // Without normal_indices, mesh2 uses the normal with the vertex's index (POV-Ray rule).
    if (!mesh.normals.empty()) {
        for (auto& f : mesh.faces)
            if (f.n[0] < 0 && mesh.normals.size() == mesh.positions.size()) f.n = f.v;
    }
    if (!mesh.uvs.empty()) {
        for (auto& f : mesh.faces)
            if (f.uv[0] < 0 && mesh.uvs.size() == mesh.positions.size()) f.uv = f.v;
    }
}

}  // namespace

BodyEnd parse_mesh_body(Parser& p, const ObjectStart& start, PovObject& po) {
    const std::string& w = start.keyword;
    scene::Mesh mesh;
    mesh.loc = start.keyword_loc;
    if (w == "mesh") {
        for (;;) {
            if (p.accept("triangle")) parse_mesh_triangle(p, mesh, false);
            else if (p.accept("smooth_triangle")) parse_mesh_triangle(p, mesh, true);
            else break;
            p.check_triangle_budget(mesh.faces.size(), start.keyword_loc);
        }
    } else {
        parse_mesh2(p, mesh);
    }
    p.check_triangle_budget(mesh.faces.size(), start.keyword_loc);
    p.count_triangles(mesh.faces.size());
    if (p.accept("inside_vector")) {
        mesh.has_inside_vector = true;
        mesh.inside_vector = p.parse_vector();
    }
    if (mesh.faces.empty()) p.fail_at(start.keyword_loc, "the " + w + " has no triangles");
    p.scene.meshes.push_back(std::move(mesh));
    po.obj.shape = scene::MeshRef{static_cast<int>(p.scene.meshes.size()) - 1};
    return BodyEnd::Modifiers;
}

}  // namespace glint::pov
