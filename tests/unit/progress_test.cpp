// Progress reporting: the `progress <fraction>` line contract, monotone output under
// concurrent updates, and the terminal bar.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "app/progress.h"

using glint::app::ProgressReporter;
using glint::app::ProgressStyle;

namespace {

std::string contents(std::FILE* f) {
    std::fflush(f);
    std::rewind(f);
    std::string s;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    return s;
}

}  // namespace

TEST(IoProgress, LinesHaveTwoDecimalsAndSkipRepeats) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        ProgressReporter p(ProgressStyle::Lines, f);
        p.update(0.0);
        p.update(0.004);  // same hundredth as 0: not repeated
        p.update(0.42);
        p.update(0.3);    // going back is ignored
        p.update(0.429);  // still 0.42
        p.finish();
        p.finish();  // idempotent
    }
    EXPECT_EQ(contents(f), "progress 0.00\nprogress 0.42\nprogress 1.00\n");
    std::fclose(f);
}

TEST(IoProgress, NoneWritesNothing) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        ProgressReporter p(ProgressStyle::None, f);
        p.update(0.5);
        p.finish();
    }
    EXPECT_EQ(contents(f), "");
    std::fclose(f);
}

TEST(IoProgress, ConcurrentUpdatesStayMonotone) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        ProgressReporter p(ProgressStyle::Lines, f);
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([&p, t] {
                for (int i = t; i <= 1000; i += 4) p.update(i / 1000.0);
            });
        for (std::thread& t : threads) t.join();
        p.finish();
    }
    std::string out = contents(f);
    double last = -1;
    size_t pos = 0;
    int lines = 0;
    while (pos < out.size()) {
        size_t end = out.find('\n', pos);
        ASSERT_NE(end, std::string::npos);
        std::string line = out.substr(pos, end - pos);
        ASSERT_EQ(line.rfind("progress ", 0), 0u) << line;
        double v = std::stod(line.substr(9));
        EXPECT_GT(v, last);
        last = v;
        ++lines;
        pos = end + 1;
    }
    EXPECT_EQ(last, 1.0);
    EXPECT_LE(lines, 101);
    std::fclose(f);
}

TEST(IoProgress, BarRedrawsOneLineAndEndsIt) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        ProgressReporter p(ProgressStyle::Bar, f);
        p.update(0.5);
        p.finish();
    }
    std::string out = contents(f);
    EXPECT_EQ(out.find('\n'), out.size() - 1);  // one line, ended once
    EXPECT_NE(out.find(" 50%"), std::string::npos);
    EXPECT_NE(out.find("100%"), std::string::npos);
    EXPECT_NE(out.find('\r'), std::string::npos);
    std::fclose(f);
}

TEST(IoProgress, AbandonEndsTheBarWithoutClaimingCompletion) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        ProgressReporter p(ProgressStyle::Bar, f);
        p.update(0.25);
        p.abandon();
        p.update(0.9);  // ignored after abandon
    }
    std::string out = contents(f);
    EXPECT_EQ(out.find("100%"), std::string::npos);
    EXPECT_EQ(out.find(" 90%"), std::string::npos);
    EXPECT_EQ(out.back(), '\n');
    std::fclose(f);
}
