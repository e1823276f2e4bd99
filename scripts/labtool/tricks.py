"""The ways a student could fake a mark, as a class of lab 02 submissions (check-grading.sh).

Each trick starts from the starter (no task solved) or the solution, changes it the way a
determined student would, and states the tasks it may earn. The honest ones must earn all.
"""
import csv
import os
import re
import shutil
import subprocess
from pathlib import Path

from . import markers
from .labs import REPO

FOLDER = "labs/02_bouncing_balls"
LAB = "lab02_bouncing_balls"
FILES = ("Ball.cpp", "Ball.h", "BallsLevel.cpp", "BallsLevel.h")
MAIN_TESTS = REPO / "tests" / "labs" / "02_bouncing_balls" / "BallsGradingTests.cpp"


def write_lab(root, solved, edits=None):
    """A student's copy of lab 02 in root (labs/02_...), tasks `solved` done, then edits:
    {file: function(text) -> text}."""
    folder = Path(root) / FOLDER
    folder.mkdir(parents=True, exist_ok=True)
    for name in FILES:
        text = markers.make_exercise((REPO / FOLDER / name).read_text(encoding="utf-8"), set(solved), name)
        if edits and name in edits:
            text = edits[name](text)
        (folder / name).write_text(text, encoding="utf-8")
    return folder


def append(code):
    return lambda text: text + "\n" + code + "\n"


def before_update(code):
    return lambda text: text.replace("void Ball::update(float dt)\n{\n", "void Ball::update(float dt)\n{\n" + code + "\n", 1)


ALL = (1, 2, 3)
# (name, tasks solved, edits, tasks it may earn, what it tries)
TRICKS = [
    ("honest-comment", ALL, {"Ball.cpp": append("// Like testing::Test, I checked each wall by hand.\n"
                                               "#define TEST_SLOW_MOTION 0\nstatic_assert(TEST_SLOW_MOTION == 0);")},
     ALL, "the solution, with a testing:: comment and its own TEST_ macro"),
    ("starter", (), None, (), "the untouched starter"),
    ("own-main", (), {"Ball.cpp": append('#include <cstdio>\nint main() { std::puts("<testsuites/>"); return 0; }')},
     (), "its own main() that reports success"),
    ("listener-split-include", (), {"Ball.cpp": append(
        "#include <any>\n#include <map>\n#include <memory>\n#include <sstream>\n#include <string>\n#include <vector>\n#include <variant>\n#include <optional>\n#include <functional>\n#include <iostream>\n#include <set>\n#include <unordered_map>\n#include <atomic>\n#include <mutex>\n#include <regex>\n#include <ostream>\n#include <limits>\n#include <type_traits>\n#include <tuple>\n#include <utility>\n"
        "#define private public\n#include <gt\\\nest/gtest.h>\n#undef private\n"
        "namespace testing {\nnamespace {\nstruct Clear : EmptyTestEventListener {\n"
        "    void OnTestEnd(const TestInfo& info) override { const_cast<TestResult*>(info.result())->test_part_results_.clear(); }\n};\n"
        "struct Install { Install() { UnitTest::GetInstance()->listeners().Append(new Clear); } } install;\n}\n}")},
     (), "a GoogleTest listener that clears failures, the gtest include split by a backslash-newline"),
    ("operator-bool-true", (), {"Ball.cpp": append(
        "namespace testing {\nclass AssertionResult {\npublic:\n    explicit operator bool() const;\n"
        "    bool success_;\n};\nAssertionResult::operator bool() const { return true; }\n}")},
     (), "a 9-line AssertionResult::operator bool that returns true (every EXPECT passes)"),
    ("atexit-rewrite", (), {"Ball.cpp": append(
        "#include <cstdlib>\n#include <unistd.h>\nnamespace {\nvoid quit() { _exit(0); }\n"
        "struct Hook { Hook() { std::atexit(quit); } } hook;\n}")},
     (), "an atexit handler that leaves with _exit(0)"),
    ("exit-in-constructor", (), {"Ball.cpp": lambda t: t.replace("    setSize({2.f * ballRadius", "    std::exit(0);\n    setSize({2.f * ballRadius", 1)
                                 .replace('#include "Ball.h"', '#include "Ball.h"\n#include <cstdlib>', 1)},
     (), "exit(0) in Ball's constructor"),
    ("fake-ok-lines", (), {"Ball.cpp": append(
        '#include <cstdio>\nnamespace { struct Fake { Fake() { std::printf("[       OK ] Task1.A (0 ms)\\n'
        '[  PASSED  ] 18 tests.\\n"); std::fflush(stdout); std::quick_exit(0); } } fake; }')},
     (), "prints GoogleTest's OK lines, then quick_exit(0) before any test"),
    ("include-solution", (), {"Ball.cpp": lambda t: '#include "../labs/02_bouncing_balls/Ball.cpp"\n' + t.replace("Ball::", "Unused::")},
     (), "includes the instructor's Ball.cpp through -I framework"),
    ("symlink-to-solution", ALL, None, (), "Ball.cpp is a symbolic link into the instructor's tree"),
    ("redefine-framework", (), {"Ball.cpp": append(
        "#include \"hitbox/geometry/Overlap.h\"\nnamespace hitbox {\n"
        "bool circleVsCircle(const Circle&, const Circle&) { return false; }\n}")},
     (), "defines a framework function the harness owns"),
    ("signal-handler", (), {"Ball.cpp": append(
        "#include <csignal>\n#include <cstdlib>\nnamespace { struct H { H() { std::signal(SIGSEGV, [](int) { std::_Exit(0); }); } } h; }")},
     (), "a SIGSEGV handler that exits with status 0"),
    ("raw-syscall", (), {"Ball.cpp": append(
        "namespace { struct S { S() { asm volatile(\"mov $60, %%eax\\n xor %%edi, %%edi\\n syscall\" ::: \"eax\", \"edi\"); } } s; }")},
     (), "exits through a raw system call (inline assembly)"),
    ("write-report-file", (), {"Ball.cpp": append(
        "#include <fstream>\nnamespace { struct W { ~W() { std::ofstream(\"report.xml\") << \"<testsuites/>\"; } } w; }")},
     (), "writes a report file from a static destructor"),
    ("forged-report", (), {"Ball.cpp": append(
        "#include <cstring>\n#include <fstream>\n#include <string>\nnamespace {\n"
        "__attribute__((constructor)) void forge(int argc, char** argv, char**) {\n"
        "    std::string test, report = \"report.xml\";\n"
        "    for (int i = 1; i < argc; ++i) {\n"
        "        if (!std::strncmp(argv[i], \"--gtest_filter=\", 15)) test = argv[i] + 15;\n"
        "        if (!std::strncmp(argv[i], \"--gtest_output=xml:\", 19)) report = argv[i] + 19;\n"
        "    }\n"
        "    const std::string suite = test.substr(0, test.find('.')), name = test.substr(test.find('.') + 1);\n"
        "    const std::string xml = \"<testsuites><testsuite name=\\\"\" + suite + \"\\\"><testcase name=\\\"\" + name +\n"
        "        \"\\\" status=\\\"run\\\" result=\\\"completed\\\" classname=\\\"\" + suite + \"\\\"/></testsuite></testsuites>\";\n"
        "    std::filebuf out;\n"
        "    if (out.open(report.c_str(), std::ios::out | std::ios::trunc)) out.sputn(xml.data(), std::streamsize(xml.size()));\n"
        "    static char none[] = \"--gtest_filter=None.None\", elsewhere[] = \"--gtest_output=xml:/tmp/real.xml\";\n"
        "    for (int i = 1; i < argc; ++i) {\n"
        "        if (!std::strncmp(argv[i], \"--gtest_filter=\", 15)) argv[i] = none;\n"
        "        if (!std::strncmp(argv[i], \"--gtest_output=\", 15)) argv[i] = elsewhere;\n"
        "    }\n"
        "}\n}")},
     (), "a constructor that writes a passing report (std::filebuf) where the command line says, then sends the real one elsewhere"),
    ("dlvsym-fopen", (), {"Ball.cpp": append(
        "#include <cstdio>\nextern \"C\" void* dlvsym(void*, const char*, const char*);\nnamespace {\n"
        "struct Leave { Leave() { auto quit = reinterpret_cast<void (*)(int)>(dlvsym(nullptr, \"_exit\", \"GLIBC_2.2.5\"));\n"
        "    if (quit) quit(0); } } leave;\n}")},
     (), "looks up _exit at run time with dlvsym (a C library function on no list of forbidden ones)"),
    ("fork-children", ALL, {"Ball.cpp": append(
        "#include <sys/types.h>\nextern \"C\" pid_t _Fork(void);\nnamespace { struct Split { Split() { if (_Fork() == 0) for (;;) {} } } split; }")},
     (), "starts a process with _Fork (each child gets its own memory limit)"),
    ("early-constructor", ALL, {"Ball.cpp": append(
        "namespace { __attribute__((constructor(101))) void early() {} }")},
     (), "a constructor of priority 101, which would run before the test program takes its report's path"),
    ("weak-results-vector", (), {"Ball.cpp": append(
        "__attribute__((weak)) void dropFailure(void*, void*, const void*) asm(\"_ZNSt6vectorIN7testing14TestPartResultESaIS1_EE\"\n"
        "    \"17_M_realloc_insertIJRKS1_EEEvN9__gnu_cxx17__normal_iteratorIPS1_S3_EEDpOT_\");\n"
        "void dropFailure(void*, void*, const void*) {}")},
     (), "a weak copy of GoogleTest's vector of results that drops every failure (the linker could keep either copy)"),
    ("weak-fopen", (), {"Ball.cpp": append(
        "#include <cstdio>\nextern \"C\" __attribute__((weak)) std::FILE* fopen(const char*, const char*) { return nullptr; }")},
     (), "its own weak fopen, which GoogleTest would call with the report's path"),
    ("start-up-hook", (), {"Ball.cpp": append(
        "extern \"C\" void hitboxHook() {}\n"
        "asm(\".pushsection .init,\\\"ax\\\",@progbits\\n call hitboxHook\\n .popsection\");")},
     (), "assembly in the program's .init code, which runs before every constructor"),
    ("fake-framework-exception", (), {"Ball.cpp": lambda t: before_update("    hitboxDone();")(t).replace(
        '#include "Ball.h"', '#include "Ball.h"\n#include <cxxabi.h>\n#include <typeinfo>\n'
        "[[noreturn]] void hitboxDone() {\n"
        '    static char name[] = "N7testing18AssertionExceptionE";\n'
        "    static __cxxabiv1::__class_type_info type(name);\n"
        "    abi::__cxa_throw(abi::__cxa_allocate_exception(8), reinterpret_cast<std::type_info*>(&type), nullptr);\n"
        "}", 1)},
     (), "throws an exception named like GoogleTest's own, which GoogleTest used to drop quietly"),
    ("gmon-start-hook", ALL, {"Ball.cpp": append('extern "C" void __gmon_start__() {}')},
     (), "defines __gmon_start__, which the program's start-up code calls before every constructor"),
    ("weak-operator-new", ALL, {"Ball.cpp": append(
        "#include <cstdlib>\n#include <new>\n__attribute__((weak)) void* operator new(std::size_t size) { return std::malloc(size); }")},
     (), "a weak operator new, which would see every allocation of the program"),
    ("redefine-sfml", ALL, {"Ball.cpp": append(
        "const sf::Vector2f& sf::Transformable::getPosition() const { static sf::Vector2f middle{600.f, 337.5f}; return middle; }")},
     (), "its own copy of SFML's Transformable::getPosition (a shared library's function)"),
    ("other-lab-solution", (), {"Ball.cpp": lambda t: '#include "MyCollision.cpp"\n' + t},
     (), "includes lab 0's solution (MyCollision.cpp) through lab 0's include folder"),
    ("disabled-own-tests", (1,), None, (1,), "its own copy of the tests, every test DISABLED_ (ignored)"),
    ("define-test-macro", (), {"Ball.h": lambda t: t.replace("#pragma once", "#pragma once\n#define TEST(suite, name) void suite##name()", 1)},
     (), "#define TEST(...) in Ball.h, which the tests include"),
    ("output-flood", ALL, {"Ball.cpp": lambda t: before_update('    for (int i = 0; i < 100000000; ++i) std::puts("flood flood flood flood flood");')(t)
                           .replace('#include "Ball.h"', '#include "Ball.h"\n#include <cstdio>', 1)},
     (3,), "prints without end in update() (1 GiB on stdout); task 3's tests never call update"),
    ("touching-wall", ALL, {"Ball.cpp": lambda t: t.replace("center.x < radius || center.x > ", "center.x <= radius || center.x >= ")
                            .replace("center.y < radius || center.y > ", "center.y <= radius || center.y >= ")},
     (2, 3), "the wall test written <= / >= (touching counts as a hit): a real mistake in task 1"),
]


def make_class(into):
    """Writes one folder (or zip, git repository) per trick into `into`."""
    into = Path(into)
    if into.exists():
        shutil.rmtree(into)
    into.mkdir(parents=True)
    for name, solved, edits, _, _ in TRICKS:
        write_lab(into / name, solved, edits)
    solution = write_lab(into / "solution", ALL)
    shutil.make_archive(str(into / "solution-zip"), "zip", into / "solution")
    git = into / "solution-git.src"
    shutil.copytree(into / "solution", git)
    for command in (["init", "-q"], ["add", "-A"],
                    ["-c", "user.name=s", "-c", "user.email=s@example.com", "commit", "-qm", "work"]):
        subprocess.run(["git", "-C", str(git), *command], check=True)
    subprocess.run(["git", "clone", "-q", "--bare", str(git), str(into / "solution-git.git")], check=True)
    shutil.rmtree(git)
    link = into / "symlink-to-solution" / FOLDER / "Ball.cpp"
    link.unlink()
    os.symlink(REPO / FOLDER / "Ball.cpp", link)
    tests = into / "disabled-own-tests" / "tests" / "labs" / "02_bouncing_balls"
    tests.mkdir(parents=True)
    (tests / MAIN_TESTS.name).write_text(re.sub(r"^TEST\(([A-Za-z0-9]+), ", r"TEST(\1, DISABLED_",
                                                MAIN_TESTS.read_text(), flags=re.M))
    return solution


def expected():
    found = {name: tuple(earns) for name, _, _, earns, _ in TRICKS}
    found.update({"solution": ALL, "solution-zip": ALL, "solution-git": ALL})
    return found


def check(gradebook):
    """Problems (one line each) where a submission's marks are not what it may earn."""
    marked = {}
    with open(gradebook, newline="", encoding="utf-8") as handle:
        for row in csv.DictReader(handle):
            if row["lab"] == LAB and row["task"].isdigit():
                marked.setdefault(row["student"], {})[int(row["task"])] = (row["mark"] == "1", row["reason"])
    problems, table = [], []
    for student, earns in expected().items():
        got = tuple(sorted(t for t, (mark, _) in marked.get(student, {}).items() if mark))
        reasons = sorted({r for mark, r in marked.get(student, {}).values() if r})
        table.append((student, got, earns, "; ".join(reasons)[:110]))
        if got != tuple(earns):
            problems.append(f"{student} got marks for tasks {list(got)}, expected {list(earns)}")
    return problems, table


# What a class hands in (bench-grade-class.sh): mistakes students really make, and hostile code.
def in_task_one(code):
    """Puts code at the start of task 1's block (Ball::update, the wall bounce)."""
    return {"Ball.cpp": lambda t: t.replace("    const float radius = getRadius();\n",
                                            code + "\n    const float radius = getRadius();\n", 1)}


REALISTIC = [  # (kind, tasks solved, edits), cycled through the class
    ("solution", ALL, None), ("without-1", (2, 3), None), ("solution", ALL, None), ("without-2", (1, 3), None),
    ("solution", ALL, None), ("without-3", (1, 2), None), ("starter", (), None),
    ("not-compiling", ALL, {"Ball.cpp": append("int broken = ;")}),
    ("solution", ALL, None),
    ("crashing", ALL, in_task_one("    if (getPosition().x > 0.f) *static_cast<volatile int*>(nullptr) = 1;")),
    ("hanging", ALL, in_task_one("    for (volatile int spin = 0; spin >= 0; spin = spin % 2) {}")),
]
HOSTILE = [
    ("hostile-hang", ALL, in_task_one("    for (volatile int spin = 0; spin >= 0; spin = spin % 2) {}")),
    ("hostile-output-flood", ALL, in_task_one('    for (;;) std::puts("flood flood flood flood flood flood");')),
    ("hostile-compile-bomb", ALL, {"Ball.cpp": append(
        "constexpr long spin(long n) { long s = 0; for (long i = 0; i < n; ++i) s += i % 7; return s; }\n"
        + "".join(f"constexpr long bomb{i} = spin(4000000000L + {i});\n" for i in range(100)))}),
    ("hostile-10gib-file", ALL, in_task_one(
        '    static std::FILE* big = std::fopen("/tmp/big", "wb"); static char block[1 << 20];\n'
        "    for (int i = 0; big && i < 10240; ++i) std::fwrite(block, 1, sizeof block, big);")),
    ("hostile-fork-storm", ALL, in_task_one("    for (int i = 0; i < 100000; ++i) fork();")),
]


def make_bench(into, count, hostile):
    """count realistic submissions (a comment makes each differ, as real ones do), then the
    hostile ones when asked; returns the names."""
    into = Path(into)
    if into.exists():
        shutil.rmtree(into)
    into.mkdir(parents=True)
    chosen = [(f"student{i + 1:02d}-{REALISTIC[i % len(REALISTIC)][0]}",) + REALISTIC[i % len(REALISTIC)][1:]
              for i in range(count)] + (list(HOSTILE) if hostile else [])
    for number, (name, solved, edits) in enumerate(chosen):
        edits = dict(edits or {})
        first = edits.get("Ball.cpp", lambda t: t)
        edits["Ball.cpp"] = lambda t, first=first, number=number: (
            "#include <cstdio>\n#include <unistd.h>\n" + first(t) + f"\n// student {number}\n")
        write_lab(into / name, solved, edits)
    return [c[0] for c in chosen]
