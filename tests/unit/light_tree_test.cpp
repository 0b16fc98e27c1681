// The light tree (render/lights/light_tree.h): its probabilities sum to one from any point, the
// probability sample() reports is the one pdf() recomputes, the empirical choice frequencies
// follow it, orientation bounds only rule out emitters that truly face away, and near emitters
// are preferred to far ones.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "render/lights/light_tree.h"

namespace glint::render {
namespace {

// n small square emitters scattered in a 20-unit cube; every third one-sided (a Lambertian
// face with a random normal), the others emitting every way.
std::vector<LightTreeItem> scattered(int n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    std::vector<LightTreeItem> items;
    for (int i = 0; i < n; ++i) {
        LightTreeItem it;
        const Vec3 c(20 * U(rng) - 10, 20 * U(rng) - 10, 20 * U(rng) - 10);
        const double h = 0.05 + 0.3 * U(rng);
        it.box.extend(c - Vec3(h, h, h));
        it.box.extend(c + Vec3(h, h, h));
        it.power = 0.1 + U(rng);
        if (i % 3 == 0) {
            const double z = 2 * U(rng) - 1, phi = 2 * kPi * U(rng);
            const double r = std::sqrt(std::max(0.0, 1 - z * z));
            it.axis = Vec3(r * std::cos(phi), r * std::sin(phi), z);
            it.theta_o = 0;
            it.theta_e = kPi / 2;
        }
        items.push_back(it);
    }
    return items;
}

std::vector<Vec3> points(int n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(-12, 12);
    std::vector<Vec3> ps;
    for (int i = 0; i < n; ++i) ps.emplace_back(U(rng), U(rng), U(rng));
    return ps;
}

TEST(LightTree, ProbabilitiesSumToOneFromAnyPoint) {
    const std::vector<LightTreeItem> items = scattered(300, 1);
    const LightTree tree(items);
    ASSERT_EQ(tree.node_count(), 2 * 300 - 1);
    EXPECT_LT(tree.depth(), 40);
    for (const Vec3& p : points(50, 2)) {
        double sum = 0;
        for (int i = 0; i < 300; ++i) sum += tree.pdf(p, i);
        EXPECT_NEAR(sum, 1.0, 1e-9);
    }
}

TEST(LightTree, SampleReportsThePdfAndFollowsIt) {
    const std::vector<LightTreeItem> items = scattered(40, 3);
    const LightTree tree(items);
    const Vec3 p(1.5, -2, 0.5);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> U(0, 1);
    const int n = 200000;
    std::vector<int> count(items.size(), 0);
    for (int i = 0; i < n; ++i) {
        double u = U(rng), prob = 0;
        const int k = tree.sample(p, &u, &prob);
        ASSERT_GE(k, 0);
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        ASSERT_NEAR(prob / tree.pdf(p, k), 1.0, 1e-12);
        ++count[k];
    }
    for (size_t k = 0; k < items.size(); ++k) {
        const double expect = n * tree.pdf(p, static_cast<int>(k));
        // Four standard deviations of a binomial count.
        EXPECT_NEAR(count[k], expect, 4 * std::sqrt(expect + 1) + 1) << "item " << k;
    }
}

TEST(LightTree, RescaledUIsUniform) {
    // The u left after the pick drives the point on the emitter: it must stay uniform.
    const LightTree tree(scattered(64, 5));
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> U(0, 1);
    int below_half = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        double u = U(rng), prob;
        tree.sample(Vec3(0, 0, 0), &u, &prob);
        below_half += u < 0.5;
    }
    EXPECT_NEAR(below_half, n / 2, 4 * std::sqrt(n / 4.0));
}

TEST(LightTree, OrientationRulesOutOnlyWhatFacesAway) {
    // A one-sided emitter is given no chance only from points behind its plane; from any
    // point in front it keeps one.
    const std::vector<LightTreeItem> items = scattered(200, 7);
    const LightTree tree(items);
    int zero = 0;
    for (const Vec3& p : points(300, 8)) {
        for (int i = 0; i < 200; i += 3) {  // the one-sided ones
            const LightTreeItem& it = items[i];
            // The largest signed distance of p in front of a plane through any box point.
            double front = -kInfinity;
            for (int c = 0; c < 8; ++c) {
                const Vec3 q(c & 1 ? it.box.hi.x : it.box.lo.x, c & 2 ? it.box.hi.y : it.box.lo.y,
                             c & 4 ? it.box.hi.z : it.box.lo.z);
                front = std::max(front, dot(p - q, it.axis));
            }
            if (tree.pdf(p, i) == 0) {
                ++zero;
                EXPECT_LE(front, 1e-9) << "item " << i;
            }
        }
    }
    EXPECT_GT(zero, 0);  // the bounds do rule some out
}

TEST(LightTree, NearEmittersArePreferred) {
    std::vector<LightTreeItem> items(2);
    for (int i = 0; i < 2; ++i) {
        const Vec3 c(i == 0 ? 1.0 : 10.0, 0, 0);
        items[i].box.extend(c - Vec3(0.1, 0.1, 0.1));
        items[i].box.extend(c + Vec3(0.1, 0.1, 0.1));
        items[i].power = 1;
    }
    const LightTree tree(items);
    const double near = tree.pdf(Vec3(0, 0, 0), 0), far = tree.pdf(Vec3(0, 0, 0), 1);
    EXPECT_NEAR(near + far, 1.0, 1e-12);
    EXPECT_NEAR(near / far, 100.0, 5.0);  // power over squared distance
}

TEST(LightTree, WithoutSpaceAnItemsChanceIsItsPowerShare) {
    const std::vector<LightTreeItem> items = scattered(50, 12);
    const LightTree tree(items, /*spatial=*/false);
    double total = 0;
    for (const LightTreeItem& it : items) total += it.power;
    for (const Vec3& p : points(5, 13))
        for (int i = 0; i < 50; ++i)
            EXPECT_NEAR(tree.pdf(p, i), items[i].power / total, 1e-12);
}

TEST(LightTree, BuildIsDeterministicAndSkipsPowerless) {
    std::vector<LightTreeItem> items = scattered(100, 9);
    items[17].power = 0;
    const LightTree a(items), b(items);
    EXPECT_EQ(a.pdf(Vec3(0, 0, 0), 17), 0.0);
    for (const Vec3& p : points(10, 10))
        for (int i = 0; i < 100; ++i) EXPECT_EQ(a.pdf(p, i), b.pdf(p, i));
    EXPECT_TRUE(LightTree(std::vector<LightTreeItem>{}).empty());
    double u = 0.3, prob = 1;
    EXPECT_EQ(LightTree(std::vector<LightTreeItem>{}).sample(Vec3(), &u, &prob), -1);
}

TEST(LightTree, UnionConeBoundsBoth) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> U(0, 1);
    auto random_dir = [&] {
        const double z = 2 * U(rng) - 1, phi = 2 * kPi * U(rng);
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        return Vec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    for (int i = 0; i < 1000; ++i) {
        const Vec3 a = random_dir(), b = random_dir();
        const double ta = U(rng) * 1.5, tb = U(rng) * 1.5;
        Vec3 axis;
        double to;
        union_cone(a, ta, b, tb, &axis, &to);
        if (to >= kPi) continue;  // every direction
        // Every direction of either cone lies within the union: the axes' angles plus the
        // spreads stay within theta_o.
        auto angle = [](const Vec3& x, const Vec3& y) {
            return std::acos(std::clamp(dot(x, y), -1.0, 1.0));
        };
        // (acos near 1 rounds to about 1e-8.)
        EXPECT_LE(angle(axis, a) + ta, to + 1e-7);
        EXPECT_LE(angle(axis, b) + tb, to + 1e-7);
        EXPECT_LE(to, kPi + 1e-12);
    }
}

}  // namespace
}  // namespace glint::render
