// The mesh kernels' prefetches are in the machine code. Until 2026-12-03 they were not: GCC 12
// judged the out-of-line prefetch helper free of side effects and deleted every call to it,
// and every test still passed, since no result depends on a prefetch. Only the code shows it,
// so this reads the glint binary's disassembly (objdump, from binutils, which g++ brings) and
// counts prefetch instructions in each build's closest() and any().
#include <gtest/gtest.h>

#if defined(__x86_64__)

#include <cstdio>
#include <map>
#include <memory>
#include <string>

namespace {

// Prefetch instructions in each function of `binary`, by demangled name; functions with none
// are listed with 0.
std::map<std::string, int> prefetches_by_function(const std::string& binary, bool* ran) {
    std::map<std::string, int> counts;
    const std::string cmd = "objdump -d --no-show-raw-insn -C '" + binary + "' 2>/dev/null";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    *ran = pipe != nullptr;
    if (!pipe) return counts;
    std::string line, current;
    char buf[4096];
    const std::string header_end = ">:\n";
    while (std::fgets(buf, sizeof buf, pipe.get())) {
        line = buf;
        // "0000000000012345 <name>:" opens a function; a blank line closes it.
        const size_t open = line.find(" <");
        const bool header =
            open != std::string::npos && line.find('\t') == std::string::npos &&
            line.size() >= open + 2 + header_end.size() &&
            line.compare(line.size() - header_end.size(), header_end.size(), header_end) == 0;
        if (header) {
            current = line.substr(open + 2, line.size() - header_end.size() - (open + 2));
            counts.emplace(current, 0);
        } else if (line == "\n") {
            current.clear();
        } else if (!current.empty() && line.find("\tprefetch") != std::string::npos) {
            ++counts[current];
        }
    }
    *ran = pclose(pipe.release()) == 0;
    return counts;
}

TEST(KernelCodegen, ClosestAndAnyPrefetchInEveryBuild) {
    bool ran = false;
    const auto counts = prefetches_by_function(GLINT_BINARY, &ran);
    ASSERT_TRUE(ran) << "objdump -d " << GLINT_BINARY << " failed (binutils installed?)";
    for (const char* build : {"kernels_base", "kernels_avx2"}) {
        for (const char* fn : {"closest(", "any("}) {
            const std::string prefix =
                std::string("glint::render::") + build + "::(anonymous namespace)::" + fn;
            int found = 0, prefetches = 0;
            for (const auto& [name, n] : counts) {
                if (name.compare(0, prefix.size(), prefix) == 0) {
                    ++found;
                    prefetches += n;
                }
            }
            // More than one where the compiler keeps a lambda of it apart (clang:
            // "closest(...)::$_0::operator()") or splits off a cold part ("[clone .cold]").
            ASSERT_GE(found, 1) << prefix << "...) is not in " << GLINT_BINARY;
            // closest() has 24 and any() 12 in a Release build with GCC 12; none means they
            // were dropped.
            EXPECT_GT(prefetches, 0) << prefix << "...) has no prefetch instruction of its "
                                     << "own: prefetch() in mesh_kernels.inc must be inlined "
                                     << "(GCC deletes calls to an out-of-line copy)";
        }
    }
}

}  // namespace

#endif
