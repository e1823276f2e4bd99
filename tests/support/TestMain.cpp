// TestMain.cpp - main() of every Hitbox test program: GoogleTest's own, plus what the class
// grader needs (scripts/labtool/engine.py).
//
// The grader hands the report's path over through a pipe, read here before any lab code runs
// and never put on the command line: lab code cannot learn where the report goes, so it cannot
// write a passing one there (docs/grading.md, "Lab code cannot write the report"). Run any
// other way (a student, ctest, Visual Studio's Test Explorer) there is no pipe and this is
// GoogleTest's plain main.
#include "hitbox/platform/Platform.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace
{

// The variable naming the pipe's descriptor; scripts/labtool/engine.py sets it (REPORT_PIPE).
constexpr const char* kReportPipeVariable = "HITBOX_GRADING_REPORT_FD";

// What the grader handed over, taken before any lab code runs.
struct FromGrader
{
    std::string reportPath;             // "" when not graded
    std::vector<std::string> arguments; // the command line as it was then (Linux)
};

FromGrader& fromGrader()
{
    static FromGrader taken;
    return taken;
}

void takeFromGrader(int argc, char** argv)
{
    FromGrader& taken = fromGrader();
    taken.reportPath = hitbox::platform::takeInheritedPipe(kReportPipeVariable);
    // Nothing this program starts should look for the pipe: it is closed.
    (void)hitbox::platform::unsetEnvironmentVariable(kReportPipeVariable);
    for (int i = 0; i < argc; ++i)
        taken.arguments.emplace_back(argv[i]);
}

#if defined(__linux__)
// Priority 101 runs before every other constructor of the program (the grader refuses lab code
// that asks for a priority, or puts code in start-up, inspect.py); glibc passes constructors
// the program's arguments.
__attribute__((constructor(101))) void takeFromGraderFirst(int argc, char** argv, char**)
{
    takeFromGrader(argc, argv);
}
#else
struct TakeFromGrader
{
    TakeFromGrader() { takeFromGrader(0, nullptr); } // in the usual order: a self-check
} takeFromGraderHere;
#endif

// Lab code may have rewritten the command line (argv is writable) before main.
bool commandLineUnchanged(int argc, char** argv)
{
    const std::vector<std::string>& then = fromGrader().arguments;
    if (then.empty())
        return true; // not taken (not Linux): nothing to compare
    if (then.size() != static_cast<std::size_t>(argc))
        return false;
    for (int i = 0; i < argc; ++i)
        if (then[static_cast<std::size_t>(i)] != argv[i])
            return false;
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string& path = fromGrader().reportPath;
    if (path.empty())
    {
        testing::InitGoogleTest(&argc, argv);
        return RUN_ALL_TESTS();
    }
    if (!commandLineUnchanged(argc, argv))
    {
        std::fprintf(stderr, "the test program's command line was changed: no report\n");
        return 1;
    }
    const std::string report = "xml:" + path;
    GTEST_FLAG_SET(output, report);
    // An exception escaping a test ends the program (a failed test) instead of being caught:
    // GoogleTest quietly drops one it takes for its own, which lab code could throw.
    GTEST_FLAG_SET(catch_exceptions, false);
    testing::InitGoogleTest(&argc, argv);
    if (GTEST_FLAG_GET(output) != report || GTEST_FLAG_GET(catch_exceptions))
    {
        std::fprintf(stderr, "the test program's report was sent elsewhere: no report\n");
        return 1;
    }
    return RUN_ALL_TESTS();
}
