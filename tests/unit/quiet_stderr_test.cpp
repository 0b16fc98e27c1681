// QuietStderr sends file descriptor 2 to /dev/null while one lives and puts the same file
// back when the last one ends, nested or from several threads at once.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <thread>
#include <vector>

#include "core/quiet_stderr.h"

namespace {

std::pair<dev_t, ino_t> stderr_file() {
    struct stat st {};
    EXPECT_EQ(::fstat(STDERR_FILENO, &st), 0);
    return {st.st_dev, st.st_ino};
}

std::pair<dev_t, ino_t> dev_null() {
    struct stat st {};
    EXPECT_EQ(::stat("/dev/null", &st), 0);
    return {st.st_dev, st.st_ino};
}

TEST(QuietStderr, NestedScopesRestoreTheSameFile) {
    const auto before = stderr_file();
    {
        glint::QuietStderr outer;
        EXPECT_EQ(stderr_file(), dev_null());
        {
            glint::QuietStderr inner;
            EXPECT_EQ(stderr_file(), dev_null());
        }
        EXPECT_EQ(stderr_file(), dev_null());  // the outer one still lives
    }
    EXPECT_EQ(stderr_file(), before);
}

TEST(QuietStderr, ManyThreadsRestoreTheSameFile) {
    const auto before = stderr_file();
    std::vector<std::thread> threads;
    for (int t = 0; t < 8; ++t)
        threads.emplace_back([] {
            for (int i = 0; i < 200; ++i) glint::QuietStderr quiet;
        });
    for (auto& t : threads) t.join();
    EXPECT_EQ(stderr_file(), before);
}

TEST(QuietStderr, FirstLineOfALibraryMessage) {
    EXPECT_EQ(glint::first_line_of("Read error: hit end of file\nPNG read error: IDAT\n"),
              "Read error: hit end of file");
    EXPECT_EQ(glint::first_line_of("Not a PNG file.  \r\n"), "Not a PNG file");
    EXPECT_EQ(glint::first_line_of(""), "unknown error");
}

}  // namespace
