// mesh2's number lists (scanner.h NumberList, literal_list.h): the fast path gives the mesh the
// token-by-token path gives, bit for bit, and anything it refuses still reads and fails as
// before, at the same places.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "formats/pov/literal_list.h"
#include "formats/pov/scanner.h"
#include "pov_test_util.h"

namespace glint::pov {
namespace {

using testing::error_of;
using testing::parse;

// A mesh2 with varied number forms. With `slow`, every list holds a comment, which keeps the
// scanner from making NumberLists, so the same values go through the token path.
std::string mesh2_text(std::mt19937_64& rng, int nv, int nf, bool slow) {
    std::uniform_real_distribution<double> u(-50, 50);
    const char* forms[] = {"%.6f", "%.17g", "%g", "%.3e", "%.0f."};
    auto num = [&](double v) {
        char b[64];
        std::snprintf(b, sizeof b, forms[rng() % 5], v);
        std::string s = b;
        if (s[0] == '-' && rng() % 3 == 0) s = "- " + s.substr(1);  // a sign set apart
        return s;
    };
    const std::string c = slow ? " /* c */" : "";
    std::string t = "mesh2 {\n vertex_vectors {" + c + " " + std::to_string(nv) + ",\n";
    for (int i = 0; i < nv; ++i)
        t += "  <" + num(u(rng)) + ", " + num(u(rng)) + "," + num(u(rng)) + ">" +
             (i + 1 < nv || rng() % 2 ? ",\n" : "\n");
    t += " }\n normal_vectors {" + c + " 2, <0, 0, 1>, <.5, 1e-3, -2.> }\n";
    t += " uv_vectors {" + c + " 3, <0.25, 1>, <-1, 2e2>, <3, 4>, }\n";
    t += " face_indices {" + c + " " + std::to_string(nf);
    std::vector<int> idx;
    for (int i = 0; i < nf; ++i) {
        t += ", <" + std::to_string(rng() % nv) + ", " + std::to_string(rng() % nv) + ", " +
             std::to_string(rng() % nv) + (rng() % 4 ? "" : ".9") + ">";
    }
    t += " }\n normal_indices {" + c + " 2, <0, 1, 1>, <1, 0, 1> }\n";
    t += " uv_indices {" + c + " 1, <0, 1, 2> }\n}\n";
    return t;
}

TEST(PovNumberList, FastPathGivesTheTokenPathsMesh) {
    for (uint64_t seed : {1, 2, 3}) {
        std::mt19937_64 a(seed), b(seed);
        const std::string fast = mesh2_text(a, 300, 500, false), slow = mesh2_text(b, 300, 500, true);
        // The fast text is six lists the fast path takes; the slow one has none.
        auto file = std::make_shared<const std::string>("t.pov");
        int lists = 0;
        const int dims[] = {3, 3, 2, 3, 3, 3};
        for (const Token& t : scan(fast, file)) {
            if (t.kind != TokKind::NumberList) continue;
            LiteralList l;
            EXPECT_TRUE(read_literal_list(t.text, dims[lists % 6], &l)) << t.text.substr(0, 80);
            ++lists;
        }
        EXPECT_EQ(lists, 6);
        for (const Token& t : scan(slow, file)) EXPECT_NE(t.kind, TokKind::NumberList);
        const scene::Scene f = parse(fast), s = parse(slow);
        ASSERT_EQ(f.meshes.size(), 1u);
        ASSERT_EQ(s.meshes.size(), 1u);
        const scene::Mesh &mf = f.meshes[0], &ms = s.meshes[0];
        ASSERT_EQ(mf.positions.size(), 300u);
        EXPECT_EQ(mf.positions, ms.positions);
        EXPECT_EQ(mf.normals, ms.normals);
        ASSERT_EQ(mf.uvs.size(), ms.uvs.size());
        for (size_t i = 0; i < mf.uvs.size(); ++i) {
            EXPECT_EQ(mf.uvs[i].x, ms.uvs[i].x);
            EXPECT_EQ(mf.uvs[i].y, ms.uvs[i].y);
        }
        ASSERT_EQ(mf.faces.size(), 500u);
        for (size_t i = 0; i < mf.faces.size(); ++i) {
            EXPECT_EQ(mf.faces[i].v, ms.faces[i].v);
            EXPECT_EQ(mf.faces[i].n, ms.faces[i].n);
            EXPECT_EQ(mf.faces[i].uv, ms.faces[i].uv);
        }
    }
}

TEST(PovNumberList, ScannerMakesOneTokenOfAPlainList) {
    auto file = std::make_shared<const std::string>("t.pov");
    auto toks = scan("vertex_vectors {\n 2, <1,2,3>, <4,5,6> }", file);
    ASSERT_EQ(toks.size(), 5u);  // word { list } end
    EXPECT_EQ(toks[2].kind, TokKind::NumberList);
    EXPECT_EQ(toks[2].line, 1);
    EXPECT_EQ(toks[2].column, 17);
    EXPECT_EQ(toks[3].line, 2);
    EXPECT_EQ(toks[3].column, 22);
    // A name, a comment or a directive inside: ordinary tokens.
    for (const char* t : {"vertex_vectors { 1, <a, 2, 3> }", "face_indices { 1, /**/ <0,1,2> }",
                          "face_indices { 1,\n#if (1) <0,1,2> #end }"})
        for (const Token& k : scan(t, file)) EXPECT_NE(k.kind, TokKind::NumberList) << t;
    LiteralList l;
    EXPECT_TRUE(read_literal_list("2, <1, -2, 3e1>, <.5, 5., - 6>,", 3, &l));
    EXPECT_EQ(l.values, (std::vector<double>{1, -2, 30, 0.5, 5, -6}));
    EXPECT_EQ(l.tokens, 20);  // count and comma, two vectors of 8 (signs included), two commas
    for (const char* bad : {"2, <1,2,3>", "1, <1,2>", "1 <1,2,3> <4,5,6>", "1, <+1,2,3>",
                            "1, <1,2,3>, <4,5,6>", "-1", "99999999, <1,2,3>", "1, <1e999,2,3>"})
        EXPECT_FALSE(read_literal_list(bad, 3, &l)) << bad;
}

// What the fast path refuses reads token by token, with the messages and places of before:
// the same text with form feeds for spaces (white space to the scanner, but not a list
// character, so no NumberList forms, and no column moves) fails identically.
std::string without_lists(std::string t) {
    for (char& c : t)
        if (c == ' ') c = '\f';
    return t;
}

TEST(PovNumberList, RefusedListsFailWhereTheyDidBefore) {
    for (const char* t : {
             "mesh2 {\n vertex_vectors { 2, <0,0,0>, <1,0,0>, <0,1,0> }\n}",
             "mesh2 {\n vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0> }\n}",
             "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
             "  face_indices { 1,\n   <0, 1, 3> } }",
             "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
             "  face_indices { 1, <0, 1, 2> }\n  normal_indices { 1, <0, 0, 0> } }",
             "mesh2 { vertex_vectors { 1, <1e999, 0, 0> } }",
             "mesh2 { vertex_vectors { 1, <1, 0> } }",
             "mesh2 { vertex_vectors { 2, <1, 0, 0> <0, 1, 0> } }",
             "mesh2 { vertex_vectors { -1 } }",
             "mesh2 { vertex_vectors { 1, <1, 0, 0>, } face_indices { 1, <0, -1, 0> } }",
         }) {
        const std::string fast = error_of(t), slow = error_of(without_lists(t));
        EXPECT_NE(fast, "(no error)") << t;
        EXPECT_EQ(fast, slow) << t;
    }
}

// The tokens a fast list stands for count against --max-tokens as they did one by one.
TEST(PovNumberList, TokensCountAgainstTheLimit) {
    std::string t = "mesh2 { vertex_vectors { 1000";
    for (int i = 0; i < 1000; ++i) t += ", <1, 2, 3>";
    t += " } face_indices { 1, <0, 1, 2> } }";
    ParseOptions o;
    o.max_tokens = 5000;  // the list alone is 1 + 1000 * 8 tokens
    EXPECT_NE(error_of(t, o).find("exceeds the token limit (5000)"), std::string::npos)
        << error_of(t, o);
    o.max_tokens = 20000;
    EXPECT_EQ(error_of(t, o), "(no error)");
}

}  // namespace
}  // namespace glint::pov
