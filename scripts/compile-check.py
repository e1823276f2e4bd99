#!/usr/bin/env python3
"""Compiles every source of a configured Linux build again, compile-only (-fsyntax-only),
with another compiler and warnings as errors wherever the build has them, so code that only
one compiler accepts fails CI.

  compile-check.py mingw  BUILD_DIR SFML_INCLUDE GTEST_INCLUDE [MORE_INCLUDES...]
      For 64-bit Windows with Debian's mingw-w64, with mingw's copy of Microsoft's C runtime
      deprecations switched on (-D__MINGW_MSVC_COMPAT_WARNINGS: getenv, localtime, strerror,
      getpid... warn where MSVC's C4996 would), against SFML's, GoogleTest's and GoogleMock's headers (they
      are the same on every platform). A POSIX-only call does not compile: its header is not
      there. mingw's own deprecation of ::hypot (MSVC's is fine) is the one warning let through.
  compile-check.py libc++ BUILD_DIR
      With clang and LLVM's libc++ (the library Apple's toolchain uses): finds a header that
      libstdc++ happens to include for you.

BUILD_DIR's compile_commands.json lists the sources, include folders and definitions (every
layer, lab solutions and generated exercises, Pong, the tests). Benchmarks are left out:
Google Benchmark is not built for Windows. Exit 1 when a source fails, naming it.
Options (after the arguments): --skip OTHER_BUILD leaves out the sources OTHER_BUILD's
compile_commands.json lists (already built for real there); --only TEXT keeps only the
sources whose path contains TEXT (to try one file by hand).
"""
import concurrent.futures
import json
import os
import shlex
import subprocess
import sys

MINGW = "x86_64-w64-mingw32-g++-posix"
WARNINGS = ["-Wall", "-Wextra", "-Wpedantic"]
SKIPPED_FOLDERS = ("/tests/benchmarks/",)


def kept_flags(arguments, system_include_ok):
    """Include folders, definitions, forced includes and the standard from one compile line."""
    flags = []
    index = 1  # arguments[0] is the compiler
    while index < len(arguments):
        argument = arguments[index]
        if argument in ("-I", "-isystem", "-D", "-include") and index + 1 < len(arguments):
            argument, index = argument + arguments[index + 1], index + 1
        if argument == "-w" or argument.startswith("-Wno-"):
            flags.append(argument)  # warnings the build turned off on purpose stay off
        for prefix in ("-I", "-isystem", "-D", "-include", "-std="):
            if argument.startswith(prefix):
                value = argument[len(prefix):]
                if prefix in ("-I", "-isystem") and not system_include_ok and value.startswith("/usr/"):
                    break  # Linux's own headers must not stand in for Windows'
                flags.append(argument if prefix != "-isystem" else "-isystem" + value)
                break
        index += 1
    return flags


def command_for(entry, kind, extra):
    arguments = entry.get("arguments") or shlex.split(entry["command"])
    source = os.path.join(entry["directory"], entry["file"])
    if kind == "mingw":
        compiler = [MINGW, "-D__MINGW_MSVC_COMPAT_WARNINGS", "-Wno-error=deprecated-declarations"]
        flags = kept_flags(arguments, system_include_ok=False)
        flags += ["-isystem" + folder for folder in extra]
    else:
        compiler = ["clang++", "-stdlib=libc++"]
        flags = kept_flags(arguments, system_include_ok=True)
    # Warnings are errors where the Linux build made them errors (everywhere but generated
    # student-like code, such as lab 0's planted mistakes); a deprecated call always fails.
    strict = ["-Werror"] if "-Werror" in arguments else []
    return source, compiler + ["-fsyntax-only"] + WARNINGS + strict + flags + [source]


def problem_in(kind, output):
    """The compiler's complaint that fails the check, or "" when there is none."""
    if kind != "mingw":
        return ""  # a warning is an error exactly where the build says so (-Werror)
    lines = output.splitlines()
    for number, line in enumerate(lines):
        if "-Wdeprecated-declarations" in line:
            context = "\n".join(lines[max(0, number - 3):number + 1])
            if "hypot" not in line:
                return context
    return ""


def main():
    arguments, skip, only = sys.argv[:], set(), ""
    while len(arguments) >= 2 and arguments[-2] in ("--skip", "--only"):
        option, value = arguments[-2], arguments[-1]
        del arguments[-2:]
        if option == "--only":
            only = value
            continue
        try:
            with open(os.path.join(value, "compile_commands.json"), encoding="utf-8") as file:
                skip |= {os.path.realpath(entry["file"]) for entry in json.load(file)}
        except (OSError, ValueError) as error:
            print(f"compile-check: cannot read {value}/compile_commands.json: {error}",
                  file=sys.stderr)
            return 2
    sys.argv = arguments
    if len(sys.argv) < 3 or sys.argv[1] not in ("mingw", "libc++") or \
            (sys.argv[1] == "mingw" and len(sys.argv) < 5):
        print(__doc__.strip().splitlines()[0], file=sys.stderr)
        print("usage: compile-check.py mingw BUILD_DIR SFML_INCLUDE GTEST_INCLUDE [MORE...] | "
              "compile-check.py libc++ BUILD_DIR", file=sys.stderr)
        return 2
    kind, build = sys.argv[1], sys.argv[2]
    database = os.path.join(build, "compile_commands.json")
    try:
        with open(database, encoding="utf-8") as file:
            entries = json.load(file)
    except (OSError, ValueError) as error:
        print(f"compile-check: cannot read {database}: {error}", file=sys.stderr)
        return 2
    entries = [entry for entry in entries
               if not any(folder in entry["file"] for folder in SKIPPED_FOLDERS)
               and os.path.realpath(entry["file"]) not in skip and only in entry["file"]]
    jobs = [command_for(entry, kind, sys.argv[3:]) for entry in entries]

    def run(job):
        source, command = job
        result = subprocess.run(command, capture_output=True, text=True)
        output = result.stdout + result.stderr
        if result.returncode != 0:
            return source, output
        return source, problem_in(kind, output)

    failed = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for source, problem in pool.map(run, jobs):
            if problem:
                failed += 1
                print(f"compile-check ({kind}): {source} does not compile:\n{problem}")
    print(f"compile-check ({kind}): {len(jobs) - failed} of {len(jobs)} sources compile"
          + ("" if kind == "libc++" else " for Windows"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
