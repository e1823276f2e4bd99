"""Unit tests of scripts/labtool/cmakeapi.py: a target's link command read from CMake's file API,
on a small reply written here (the shape CMake 3.25 writes, cut to one target), and on a tiny
project configured by the real CMake, against what its generators link with.

    python3 tests/scripts/test_cmakeapi.py      (ctest: scripts.LabTool)
"""
import json
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from labtool import cmakeapi  # noqa: E402

SOURCE = Path("/src/hitbox")
TARGET = "lab99_demo_tests"
FOLDER = "tests/labs/99_demo"


def write_json(path, value):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(value, indent=1), encoding="utf-8")


def fixture_build(generator):
    """A configured build folder with the replies of one test program: two test sources (the
    first also compiled into the exercise's tests), the lab's archive and a system library."""
    build = Path(tempfile.mkdtemp(prefix="cmakeapi-test-"))
    (build / "CMakeCache.txt").write_text("# a configured build\n", encoding="utf-8")
    top = generator.startswith("Ninja")
    lab_archive = ("" if top else "../../../") + "labs/99_demo/liblab99_demo_level.a"
    reply = build / ".cmake/api/v1/reply"
    write_json(reply / "index-2026-01-01T00-00-00-0000.json", {"reply": {}})  # an older, stale index
    write_json(reply / "index-2026-11-28T14-00-00-0000.json", {
        "cmake": {"generator": {"multiConfig": False, "name": generator}},
        "reply": {"codemodel-v2": {"jsonFile": "codemodel-v2-1.json", "kind": "codemodel"},
                  "cache-v2": {"jsonFile": "cache-v2-1.json", "kind": "cache"}}})
    write_json(reply / "codemodel-v2-1.json", {
        "paths": {"build": str(build), "source": str(SOURCE)},
        "configurations": [{"name": "Debug", "targets": [
            {"name": "lab99_demo_level", "jsonFile": "target-level.json"},
            {"name": TARGET, "jsonFile": "target-tests.json"}]}]})
    write_json(reply / "cache-v2-1.json", {"entries": [
        {"name": "CMAKE_CXX_COMPILER", "type": "FILEPATH", "value": "/usr/bin/c++"},
        {"name": "CMAKE_CXX_COMPILER_LAUNCHER", "type": "STRING", "value": "ccache"}]})
    write_json(reply / "target-level.json", {"name": "lab99_demo_level", "type": "STATIC_LIBRARY"})
    write_json(reply / "target-tests.json", {
        "name": TARGET, "type": "EXECUTABLE",
        "artifacts": [{"path": f"{FOLDER}/{TARGET}"}],
        "paths": {"build": FOLDER, "source": FOLDER},
        "sources": [{"path": f"{FOLDER}/DemoTests.cpp", "compileGroupIndex": 0},
                    {"path": f"{FOLDER}/DemoTests.h"},
                    {"path": "tests/labs-hidden/99_demo/DemoHidden.cpp", "compileGroupIndex": 0}],
        "link": {"language": "CXX", "commandFragments": [
            {"fragment": "-g", "role": "flags"}, {"fragment": "", "role": "flags"},
            {"fragment": lab_archive, "role": "libraries"},
            {"fragment": "/usr/lib/libgtest.a", "role": "libraries"},
            {"fragment": "-ldl", "role": "libraries"}]}})
    # compile_commands.json: Makefiles compile in the target's folder, Ninja in the top one.
    compile_dir = build if top else build / FOLDER
    prefix = f"{FOLDER}/" if top else ""
    commands = []
    for target in (TARGET, "lab99_demo_exercise_tests"):
        for source, obj in ((f"{FOLDER}/DemoTests.cpp", "DemoTests.cpp.o"),
                            ("tests/labs-hidden/99_demo/DemoHidden.cpp", "__/__/labs-hidden/99_demo/DemoHidden.cpp.o")):
            output = f"{prefix}CMakeFiles/{target}.dir/{obj}"
            commands.append({"directory": str(compile_dir), "file": str(SOURCE / source),
                             "command": f"ccache /usr/bin/c++ -g -o {output} -c {SOURCE / source}"})
    write_json(build / "compile_commands.json", commands)
    return build


class FromAFixtureReply(unittest.TestCase):
    def link(self, generator):
        build = fixture_build(generator)
        self.addCleanup(shutil.rmtree, build, True)
        return build, cmakeapi.link_command(build, TARGET)

    def test_a_makefile_build_links_in_the_target_folder_as_its_link_txt_says(self):
        build, link = self.link("Unix Makefiles")
        self.assertEqual(link.directory, build / FOLDER)
        self.assertEqual(link.words(), [
            "/usr/bin/c++", "-g", f"CMakeFiles/{TARGET}.dir/DemoTests.cpp.o",
            f"CMakeFiles/{TARGET}.dir/__/__/labs-hidden/99_demo/DemoHidden.cpp.o", "-o", TARGET,
            "../../../labs/99_demo/liblab99_demo_level.a", "/usr/lib/libgtest.a", "-ldl"])

    def test_a_ninja_build_links_in_the_top_folder(self):
        build, link = self.link("Ninja")
        self.assertEqual(link.directory, build)
        self.assertEqual(link.objects, (f"{FOLDER}/CMakeFiles/{TARGET}.dir/DemoTests.cpp.o",
                                        f"{FOLDER}/CMakeFiles/{TARGET}.dir/__/__/labs-hidden/99_demo/DemoHidden.cpp.o"))
        self.assertEqual(link.output, f"{FOLDER}/{TARGET}")
        self.assertEqual(link.path(link.output), build / FOLDER / TARGET)

    def test_the_compiler_is_the_cache_s_not_its_launcher(self):
        self.assertEqual(self.link("Unix Makefiles")[1].compiler, "/usr/bin/c++")

    def test_the_lab_archive_is_swapped_for_objects_where_it_was_linked(self):
        for generator in ("Unix Makefiles", "Ninja"):
            build, link = self.link(generator)
            swapped = link.swap_library(build / "labs/99_demo/liblab99_demo_level.a", ["a.o", "b.o"])
            self.assertEqual(swapped.libraries, ("a.o", "b.o", "/usr/lib/libgtest.a", "-ldl"), generator)
            self.assertEqual(swapped.objects, link.objects)

    def test_swapping_an_archive_the_program_does_not_link_says_so(self):
        build, link = self.link("Unix Makefiles")
        with self.assertRaisesRegex(cmakeapi.LinkError, "does not name .*liblab98"):
            link.swap_library(build / "labs/98/liblab98_level.a", [])

    def test_an_unknown_target_is_one_line(self):
        build = fixture_build("Unix Makefiles")
        self.addCleanup(shutil.rmtree, build, True)
        with self.assertRaises(cmakeapi.LinkError) as caught:
            cmakeapi.link_command(build, "lab98_nothing_tests")
        self.assertIn("no target lab98_nothing_tests", str(caught.exception))
        self.assertNotIn("\n", str(caught.exception))

    def test_a_visual_studio_build_is_refused_not_guessed(self):
        build = fixture_build("Visual Studio 17 2022")
        self.addCleanup(shutil.rmtree, build, True)
        with self.assertRaisesRegex(cmakeapi.LinkError, "Makefile or Ninja"):
            cmakeapi.link_command(build, TARGET)

    def test_a_folder_cmake_never_configured_is_refused_without_running_cmake(self):
        build = Path(tempfile.mkdtemp(prefix="cmakeapi-test-"))
        self.addCleanup(shutil.rmtree, build, True)
        with self.assertRaisesRegex(cmakeapi.LinkError, "not a configured build folder"):
            cmakeapi.link_command(build, TARGET)
        self.assertFalse((build / ".cmake").exists())


TINY_PROJECT = """cmake_minimum_required(VERSION 3.16)
project(Tiny LANGUAGES CXX)
add_library(part STATIC part.cpp)
add_executable(tiny_tests main.cpp extra/more.cpp)
target_link_libraries(tiny_tests PRIVATE part)
"""


@unittest.skipUnless(shutil.which("cmake") and shutil.which("c++"), "needs CMake and a C++ compiler")
class AgainstRealCMake(unittest.TestCase):
    """The words CMake's own generators link with, for a project configured here (no build)."""

    def configure(self, generator):
        root = Path(tempfile.mkdtemp(prefix="cmakeapi-tiny-"))
        self.addCleanup(shutil.rmtree, root, True)
        (root / "extra").mkdir()
        for name, text in (("CMakeLists.txt", TINY_PROJECT), ("part.cpp", "int part() { return 1; }\n"),
                           ("main.cpp", "int main() { return 0; }\n"), ("extra/more.cpp", "int more;\n")):
            (root / name).write_text(text, encoding="utf-8")
        build = root / "build"
        subprocess.run(["cmake", "-S", str(root), "-B", str(build), "-G", generator,
                        "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON"], check=True, capture_output=True)
        return build

    def test_a_makefile_build_gives_its_link_txt(self):
        build = self.configure("Unix Makefiles")
        link_txt = (build / "CMakeFiles/tiny_tests.dir/link.txt").read_text(encoding="utf-8")
        link = cmakeapi.link_command(build, "tiny_tests")  # (re-runs cmake: no query was written)
        # CMake 3.27 and newer add the generator's own bookkeeping to link.txt (the linker
        # writes link.d, which make reads to know when to relink): not part of what is linked.
        linked = [word for word in shlex.split(link_txt) if not word.startswith("-Wl,--dependency-file=")]
        self.assertEqual(link.words(), linked)
        self.assertEqual(link.directory, build)

    @unittest.skipUnless(shutil.which("ninja"), "needs Ninja")
    def test_a_ninja_build_gives_the_command_ninja_links_with(self):
        build = self.configure("Ninja")
        commands = subprocess.run(["ninja", "-C", str(build), "-t", "commands", "tiny_tests"], check=True,
                                  capture_output=True, text=True).stdout.strip().splitlines()
        linked = re.sub(r"^: && | && :$", "", commands[-1])
        link = cmakeapi.link_command(build, "tiny_tests")
        self.assertEqual(link.words(), shlex.split(linked))
        self.assertEqual(link.directory, build)


if __name__ == "__main__":
    unittest.main()
