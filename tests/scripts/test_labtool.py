"""Unit tests of the lab tool's self-check (scripts/labtool/selfcheck.py): the object check a
student's `lab.py grade` runs, on objects compiled here, and what it does without binutils.

    python3 -m unittest discover -s tests/scripts      (ctest: scripts.LabTool)
"""
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path
from unittest import mock

sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from labtool import selfcheck  # noqa: E402

HAVE_TOOLS = all(shutil.which(tool) for tool in ("c++", *selfcheck.BINUTILS))


class TimeLimitReason(unittest.TestCase):
    """A hang reads the same way however the limit stopped it (the class grades' reason column
    must not change between two runs of the same submissions)."""

    def test_a_kill_at_the_time_limit_is_a_time_out_not_a_crash(self):
        from labtool import procs
        hang = procs.Outcome(status=-9, seconds=5.3, timed_out=False, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(hang, 5, 1_000_000),
                         "the test took longer than 5 s (an endless loop?)")

    def test_a_kill_before_the_limit_is_still_a_crash(self):
        from labtool import procs
        early = procs.Outcome(status=-9, seconds=0.4, timed_out=False, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(early, 5, 1_000_000), "crashed: SIGKILL")

    def test_a_test_is_judged_by_its_cpu_time_not_by_how_busy_the_machine_is(self):
        from labtool import limits, procs
        cpu, wall = limits.TEST_SECONDS, limits.TEST_WALL_SECONDS
        self.assertGreater(wall, cpu)
        # 6 s of wall-clock time on a busy machine, not stopped: nothing to report.
        slow = procs.Outcome(status=0, seconds=cpu + 1, timed_out=False, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(slow, cpu, 1_000_000, wall_seconds=wall), "")
        # Killed by the CPU limit: says so, however long it took on the clock.
        cpu_killed = procs.Outcome(status=-9, seconds=cpu + 3, timed_out=False, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(cpu_killed, cpu, 1_000_000, wall_seconds=wall),
                         f"the test used more than {cpu:g} s of CPU time")
        # A test that waits is caught by the guard.
        waited = procs.Outcome(status=-9, seconds=wall, timed_out=True, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(waited, cpu, 1_000_000, wall_seconds=wall),
                         f"the test took longer than {wall:g} s (an endless loop?)")

    def test_a_compile_is_judged_by_its_cpu_time_not_by_how_busy_the_machine_is(self):
        from labtool import limits, procs
        cpu, wall = limits.COMPILE_SECONDS, limits.COMPILE_WALL_SECONDS
        self.assertGreater(wall, cpu)
        # Killed by the CPU limit after 70 s of wall-clock time on a busy machine.
        cpu_killed = procs.Outcome(status=-9, seconds=cpu + 10, timed_out=False, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(cpu_killed, cpu, 1_000_000, what="compiling", wall_seconds=wall),
                         f"compiling used more than {cpu:g} s of CPU time")
        # Only the wall-clock guard stops a compiler that waits (it cannot be seen in CPU time).
        waited = procs.Outcome(status=-9, seconds=wall, timed_out=True, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(waited, cpu, 1_000_000, what="compiling", wall_seconds=wall),
                         f"compiling took longer than {wall:g} s (an endless loop?)")
        # A kill before the CPU limit could be reached is not the limit's.
        early = procs.Outcome(status=-9, seconds=cpu - 1, timed_out=False, output="", output_bytes=0)
        self.assertEqual(procs.why_stopped(early, cpu, 1_000_000, what="compiling", wall_seconds=wall),
                         "crashed: SIGKILL")


class FakeLab:
    """What object_check reads of a lab: its name, folder and the files a student edits."""

    name = "lab99_demo"
    folder = "labs/99_demo"
    student_files = ["Demo.cpp", "Demo.h"]


def build_with(student_source):
    """A build folder laid out as CMake lays out a lab: the student's Demo.cpp compiled into
    the lab library's object folder, and the lab's own (non-student) Level.cpp beside it."""
    build = Path(tempfile.mkdtemp(prefix="labtool-test-"))
    level = build / FakeLab.folder / "CMakeFiles" / f"{FakeLab.name}_level.dir"
    level.mkdir(parents=True)
    for name, text in (("Demo.cpp", student_source), ("Level.cpp", "int levelWidth() { return 1200; }\n")):
        source = build / name
        source.write_text(text, encoding="utf-8")
        subprocess.run(["c++", "-c", str(source), "-o", str(level / f"{name}.o")], check=True)
    (build / "tests" / FakeLab.folder / "CMakeFiles" / f"{FakeLab.name}_tests.dir").mkdir(parents=True)
    return build


@unittest.skipUnless(HAVE_TOOLS, "needs a C++ compiler and GNU binutils")
class ObjectCheck(unittest.TestCase):
    def check(self, source):
        build = build_with(source)
        self.addCleanup(shutil.rmtree, build, True)
        return selfcheck.object_check(FakeLab, build, f"{FakeLab.name}_tests")

    def test_plain_lab_code_is_accepted(self):
        self.assertEqual(self.check("float twice(float x) { return 2.f * x; }\n"), ("", ""))

    def test_a_main_of_its_own_is_refused_with_one_line(self):
        refused, note = self.check("int main() { return 0; }\n")
        self.assertEqual(note, "")
        self.assertIn("`Demo.cpp` defines main()", refused)
        self.assertNotIn("\n", refused)

    def test_ending_the_program_is_refused(self):
        refused, _ = self.check("#include <cstdlib>\nvoid stop() { std::exit(0); }\n")
        self.assertIn("calls exit()", refused)

    def test_replacing_a_function_of_the_lab_is_refused(self):
        refused, _ = self.check("int levelWidth() { return 1; }\n")
        self.assertIn("already define", refused)

    def test_a_comment_naming_the_test_framework_is_not_refused(self):
        self.assertEqual(self.check("// testing::Test, gtest, main()\nint one() { return 1; }\n")[0], "")

    def test_maths_memory_text_and_printing_of_the_c_library_are_accepted(self):
        source = ("#include <cmath>\n#include <cstdio>\n#include <cstdlib>\n#include <cstring>\n"
                  "float f(float x, char* text, std::size_t n) { std::snprintf(text, n, \"%g\", std::atan2(x, 1.f));\n"
                  "    std::printf(\"%zu\\n\", std::strlen(text)); void* p = std::malloc(8); std::free(p);\n"
                  "    return std::sqrt(x) + float(std::atoi(text)); }\n")
        self.assertEqual(self.check(source)[0], "")

    def test_a_c_library_function_off_the_list_is_refused_even_one_no_list_names(self):
        refused, _ = self.check('extern "C" void* dlvsym(void*, const char*, const char*);\n'
                                'void* find() { return dlvsym(nullptr, "_exit", "GLIBC_2.2.5"); }\n')
        self.assertIn("calls dlvsym()", refused)
        self.assertNotIn("\n", refused)

    def test_code_that_asks_to_run_before_the_program_starts_is_refused(self):
        refused, _ = self.check("namespace { __attribute__((constructor(101))) void early() {} }\n")
        self.assertIn("before or after the test program's own start-up", refused)
        refused, _ = self.check('extern "C" void hook() {}\n'
                                'asm(".pushsection .init,\\"ax\\",@progbits\\n call hook\\n .popsection");\n')
        self.assertIn("(.init:", refused)

    def test_a_copy_of_a_c_library_function_or_of_the_test_framework_is_refused(self):
        refused, _ = self.check('#include <cstdio>\n'
                                'extern "C" __attribute__((weak)) std::FILE* fopen(const char*, const char*) { return nullptr; }\n')
        self.assertIn("fopen", refused)
        # An inline function is a weak copy in a group of its own, as templates are.
        refused, _ = self.check("namespace testing { struct TestPartResult {}; }\n"
                                "inline void drop(testing::TestPartResult*) {}\nvoid use() { drop(nullptr); }\n")
        self.assertIn("part of the test framework", refused)

    def test_a_hand_made_weak_definition_or_a_start_up_name_is_refused(self):
        refused, _ = self.check("#include <cstdlib>\n#include <new>\n"
                                "__attribute__((weak)) void* operator new(std::size_t n) { return std::malloc(n); }\n")
        self.assertIn("weak (__attribute__((weak)))", refused)
        refused, _ = self.check('extern "C" void __gmon_start__() {}\n')
        self.assertIn("start-up code calls", refused)

    def test_the_compilers_own_weak_copies_and_harmless_calls_are_accepted(self):
        source = ("#include <cstdio>\n#include <filesystem>\n#include <iostream>\n#include <string>\n#include <vector>\n"
                  "inline int twice(int x) { return 2 * x; }\n"
                  "std::string f() { std::setvbuf(stdout, nullptr, _IONBF, 0); std::vector<int> v{twice(1)};\n"
                  "    std::cout << std::filesystem::current_path() << v.size() << std::endl; return std::to_string(v[0]); }\n")
        self.assertEqual(self.check(source)[0], "")

    def test_the_plain_constructors_of_static_objects_are_accepted(self):
        self.assertEqual(self.check("#include <string>\nstd::string greeting = std::string(40, 'x');\n")[0], "")

    def test_listing_a_folder_is_refused(self):
        refused, _ = self.check("#include <filesystem>\nint count() { int n = 0;\n"
                                "    for (const auto& entry : std::filesystem::directory_iterator(\".\")) n += !entry.path().empty();\n"
                                "    return n; }\n")
        self.assertIn("list folders", refused)


class Submissions(unittest.TestCase):
    def test_a_zip_that_unpacks_too_big_is_refused_before_anything_is_written(self):
        import zipfile
        from labtool import limits, submission
        folder = Path(tempfile.mkdtemp(prefix="labtool-test-"))
        self.addCleanup(shutil.rmtree, folder, True)
        bomb = folder / "bomb.zip"
        with zipfile.ZipFile(bomb, "w", zipfile.ZIP_DEFLATED) as archive:
            archive.writestr("labs/02_bouncing_balls/Ball.cpp", b"\0" * (limits.SUBMISSION_BYTES + 1))
        (folder / "into").mkdir()
        with self.assertRaises(submission.Refused) as refused:
            submission.unpack(bomb, folder / "into")
        self.assertIn("at most", str(refused.exception))
        self.assertEqual(list((folder / "into").rglob("*")), [])

    def test_a_file_name_cannot_add_lines_or_formatting_to_the_feedback(self):
        from labtool.submission import printable_name
        shown = printable_name("a\n## Everything passed\n`b`")
        self.assertNotIn("\n", shown)
        self.assertNotIn("`", shown)


class WithoutBinutils(unittest.TestCase):
    def test_it_says_so_in_one_line_and_refuses_nothing(self):
        with mock.patch.object(selfcheck.shutil, "which", return_value=None):
            refused, note = selfcheck.object_check(FakeLab, Path(tempfile.gettempdir()), f"{FakeLab.name}_tests")
        self.assertEqual(refused, "")
        self.assertIn("GNU binutils", note)
        self.assertNotIn("\n", note)


class OnWindows(unittest.TestCase):
    """The self-check needs no bash, bubblewrap, prlimit or binutils: faked Windows here."""

    def test_the_self_check_imports_without_posix_modules(self):
        # fcntl, resource, pwd and grp do not exist on Windows: importing the self-check's
        # modules must not need them (class grading's sandbox is imported only to grade a class).
        code = ("import sys\n"
                "for name in ('fcntl', 'resource', 'pwd', 'grp'): sys.modules[name] = None\n"
                f"sys.path.insert(0, {str(Path(selfcheck.__file__).parents[1])!r})\n"
                "import lab, labtool.selfcheck, labtool.engine, labtool.procs, labtool.reports\n"
                "print('imported')\n")
        done = subprocess.run([sys.executable, "-B", "-c", code], capture_output=True, text=True)
        self.assertEqual(done.stdout.strip(), "imported", done.stderr)

    def test_the_object_check_says_it_is_not_done_in_one_line(self):
        build = Path(tempfile.gettempdir())  # (made before os.name is faked: pathlib reads it)
        with mock.patch.object(selfcheck.os, "name", "nt"):
            refused, note = selfcheck.object_check(FakeLab, build, f"{FakeLab.name}_tests")
        self.assertEqual(refused, "")
        self.assertIn("not done on Windows", note)
        self.assertNotIn("\n", note)

    def test_a_windows_test_program_is_found(self):
        # Visual Studio puts it in a folder per configuration, with .exe.
        build = Path(tempfile.mkdtemp(prefix="labtool-test-"))
        self.addCleanup(shutil.rmtree, build, True)
        program = build / "tests" / FakeLab.folder / "Debug" / f"{FakeLab.name}_tests.exe"
        program.parent.mkdir(parents=True)
        program.write_bytes(b"MZ")
        self.assertEqual(selfcheck.find_program(build, f"{FakeLab.name}_tests"), program)


if __name__ == "__main__":
    unittest.main()
