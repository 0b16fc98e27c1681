// core/fixed_list.h: the in-place list behind the path tracer's per-vertex closure lists.
#include <gtest/gtest.h>

#include "core/fixed_list.h"

namespace glint {
namespace {

struct Value {
    int a = 7;
    double b = 0.5;
};

TEST(FixedList, HoldsUpToItsCapacityAndCopiesWhatItHolds) {
    FixedList<Value, 3> list;
    EXPECT_TRUE(list.empty());
    EXPECT_TRUE(list.push_back({1, 1.5}));
    Value& d = list.emplace_back();  // built with its defaults
    EXPECT_EQ(d.a, 7);
    EXPECT_DOUBLE_EQ(d.b, 0.5);
    EXPECT_TRUE(list.push_back({3, 3.5}));
    EXPECT_TRUE(list.full());
    EXPECT_FALSE(list.push_back({4, 4.5}));  // full: refused, nothing changes
    ASSERT_EQ(list.size(), 3);
    EXPECT_EQ(list[2].a, 3);

    FixedList<Value, 3> copy = list;
    list[0].a = 100;  // the copy is its own
    ASSERT_EQ(copy.size(), 3);
    EXPECT_EQ(copy[0].a, 1);
    EXPECT_EQ(copy[1].a, 7);
    EXPECT_DOUBLE_EQ(copy[2].b, 3.5);

    copy.pop_back();
    EXPECT_EQ(copy.size(), 2);
    int sum = 0;
    for (const Value& v : copy) sum += v.a;
    EXPECT_EQ(sum, 8);
    list = copy;
    EXPECT_EQ(list.size(), 2);
    EXPECT_EQ(list[0].a, 1);
    list.clear();
    EXPECT_TRUE(list.empty());
    EXPECT_EQ(list.begin(), list.end());
}

}  // namespace
}  // namespace glint
