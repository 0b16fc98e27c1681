// Parts of a render (app/parts.h): tiles cover the image exactly once, on the driver's blocks
// where they can; regions and frame ranges read as documented, and anything else is refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "render/film/driver.h"

// The CLI is an executable, not a library the tests link: its code is compiled here.
#include "app/parts.cpp"  // NOLINT(bugprone-suspicious-include)

namespace glint::app {
namespace {

TEST(Parts, TilesCoverTheImageOnceOnBlockEdges) {
    for (int w : {1, 31, 32, 97, 640, 1921})
        for (int h : {1, 17, 64, 480, 1081})
            for (int n : {1, 2, 3, 4, 5, 7, 12, 16, 64}) {
                if (static_cast<long long>(w) * h < n) continue;
                std::vector<render::Region> tiles;
                try {
                    tiles = split_into_tiles(w, h, n);
                } catch (const Error&) {
                    // Only a prime count wider and taller than the image has no grid.
                    EXPECT_TRUE(n > w && n > h) << w << "x" << h << " n " << n;
                    continue;
                }
                ASSERT_EQ(static_cast<int>(tiles.size()), n) << w << "x" << h;
                std::vector<int> covered(static_cast<size_t>(w) * h, 0);
                for (const render::Region& t : tiles) {
                    ASSERT_FALSE(t.empty());
                    for (int y = t.y0; y < t.y1; ++y)
                        for (int x = t.x0; x < t.x1; ++x) ++covered[static_cast<size_t>(y) * w + x];
                    // Inner edges on 32-pixel blocks whenever the image has a block per tile
                    // along that side (n is at least the tiles across or down).
                    const int bw = (w + 31) / 32, bh = (h + 31) / 32;
                    if (bw >= n) {
                        EXPECT_EQ(t.x0 % render::kBlockSize, 0) << w << " n " << n;
                    }
                    if (bh >= n) {
                        EXPECT_EQ(t.y0 % render::kBlockSize, 0) << h << " n " << n;
                    }
                }
                for (int c : covered) ASSERT_EQ(c, 1) << w << "x" << h << " n " << n;
            }
}

TEST(Parts, SixteenTilesOf640x480AreAFourByFourGridOfBlocks) {
    const auto tiles = split_into_tiles(640, 480, 16);
    ASSERT_EQ(tiles.size(), 16u);
    EXPECT_EQ(region_string(tiles[0]), "0,0,160,96");
    EXPECT_EQ(region_string(tiles[5]), "160,96,320,224");
    EXPECT_EQ(region_string(tiles[15]), "480,352,640,480");
}

TEST(Parts, RegionsAndFrameRangesReadAsWritten) {
    const render::Region r = parse_region("3,4,50,60", "--region");
    EXPECT_EQ(region_string(r), "3,4,50,60");
    for (const char* bad : {"3,4,50", "3,4,50,60,1", "a,4,50,60", "3,4,3,60", "-1,0,4,4", "3 4 5 6",
                            "", "1,2,3,9999999999"}) {
        try {
            parse_region(bad, "--region");
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Usage);
            EXPECT_EQ(std::string(e.what()).rfind("--region " + std::string(bad), 0), 0u) << e.what();
        }
    }
    FrameRange f = parse_frame_range("2-7", "--frames");
    EXPECT_EQ(f.first, 2);
    EXPECT_EQ(f.last, 7);
    f = parse_frame_range("5", "--frames");
    EXPECT_EQ(f.first, 5);
    EXPECT_EQ(f.last, 5);
    for (const char* bad : {"7-2", "a-b", "1-", "-3", "1-2-3", ""})
        EXPECT_THROW(parse_frame_range(bad, "--frames"), Error) << bad;
    EXPECT_THROW(split_into_tiles(4, 4, 17), Error);
    EXPECT_THROW(split_into_tiles(4, 4, 0), Error);
}

TEST(Parts, JobSignaturesFollowSettingsAndSceneBytes) {
    const std::string a = job_signature("size=10x10", "/nonexistent/scene.pov");
    EXPECT_EQ(a.size(), 16u);
    EXPECT_EQ(a, job_signature("size=10x10", "/nonexistent/scene.pov"));
    EXPECT_NE(a, job_signature("size=10x11", "/nonexistent/scene.pov"));
}

}  // namespace
}  // namespace glint::app
