// TestMain.cpp - main() of every Hitbox test program: GoogleTest's own, plus where the report
// goes when the class grader runs the program (scripts/labtool/engine.py).
//
// The grader hands the report's path over through a pipe, read here before any lab code runs
// and never put on the command line: lab code cannot learn where the report goes, so it cannot
// write a passing one there (docs/grading.md, "Faked results"). Run any other way (a student,
// ctest, Visual Studio's Test Explorer) there is no pipe and this is GoogleTest's plain main.
#include "hitbox/platform/Platform.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace
{

// The variable naming the pipe's descriptor; scripts/labtool/engine.py sets it (REPORT_PIPE).
constexpr const char* kReportPipeVariable = "HITBOX_GRADING_REPORT_FD";

// Filled before every other static initialiser of the program (priority 101, the first a
// program may ask for; the grader refuses lab code that asks for any priority, inspect.py).
std::string& reportPathFromGrader()
{
    static std::string path;
    return path;
}

struct TakeReportPath
{
    TakeReportPath()
    {
        reportPathFromGrader() = hitbox::platform::takeInheritedPipe(kReportPipeVariable);
        // Nothing this program starts should look for the pipe: it is closed.
        (void)hitbox::platform::unsetEnvironmentVariable(kReportPipeVariable);
    }
};

#if defined(__linux__) // class grading runs on Linux only
TakeReportPath takeReportPath __attribute__((init_priority(101)));
#else
TakeReportPath takeReportPath; // in the usual order: a self-check, no cage to keep closed
#endif

} // namespace

int main(int argc, char** argv)
{
    const std::string report =
        reportPathFromGrader().empty() ? "" : "xml:" + reportPathFromGrader();
    if (!report.empty())
        GTEST_FLAG_SET(output, report);
    testing::InitGoogleTest(&argc, argv);
    if (!report.empty() && GTEST_FLAG_GET(output) != report)
    {
        std::fprintf(stderr, "the test program's report was sent elsewhere: no report\n");
        return 1;
    }
    return RUN_ALL_TESTS();
}
