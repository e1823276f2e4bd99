"""Reads a submission's compiled objects (nm, objdump) and refuses, with one line, code that
could decide its own verdict: a lab's code computes positions and collisions, it never needs
to own the program, the test framework, files or other processes.

Refused when a student object
- defines main, anything of GoogleTest (testing::, gtest), or a strong symbol the harness
  already defines (the tests, the lab's other files, the framework, GoogleTest, the C and C++
  libraries): replacing one changes what the tests see;
- calls a function that ends or leaves the process, starts processes, or writes, renames or
  deletes files (the ways to forge or hide a report; reading a file, as lab 9's level loader
  does, is allowed);
- contains a raw system call instruction.
Comments, strings and the student's own macros never matter: only compiled code is read.
"""
import re
import subprocess
from functools import lru_cache

# Called from a lab's code, these could end the test early or reach the report.
FORBIDDEN_CALLS = {
    "exit", "_exit", "_Exit", "quick_exit", "at_quick_exit", "atexit", "on_exit",
    "fork", "vfork", "clone", "clone3", "execl", "execle", "execlp", "execv", "execve", "execvp", "execvpe",
    "fexecve", "system", "popen", "posix_spawn", "posix_spawnp", "kill", "killpg", "signal", "sigaction",
    "fopen", "fopen64", "freopen", "freopen64", "open", "open64", "openat", "openat64", "creat", "creat64",
    "unlink", "unlinkat", "remove", "rename", "renameat", "truncate", "ftruncate", "write", "pwrite", "writev",
    "dup2", "dup3", "mmap", "mmap64", "mprotect", "dlopen", "dlsym", "dlmopen", "ptrace", "syscall",
    "longjmp", "_longjmp", "siglongjmp", "__longjmp_chk", "setcontext", "swapcontext", "chdir", "prctl",
}
# Mangled-name pieces of the C++ library's file writers (reading a level file is allowed: lab 9).
FORBIDDEN_CLASSES = ("basic_ofstream", "basic_fstream")
# std::filesystem operations that change files (status, exists, file_size and path are fine).
FORBIDDEN_FILESYSTEM = re.compile(r"^std::filesystem::(__cxx11::)?(remove|remove_all|rename|copy|copy_file|"
                                  r"copy_symlink|create_\w+|resize_file|permissions|current_path|"
                                  r"last_write_time)\(")
STRONG_TYPES = set("TDBRGSA")  # nm letters of a non-weak definition
RAW_SYSCALL = re.compile(r"\t(syscall|sysenter|int\s+\$0x80|svc\s+#?0)\b")
SYSTEM_LIBRARIES = ("libc.so.6", "libstdc++.so.6", "libm.so.6", "libgcc_s.so.1")


def symbols(path, dynamic=False):
    """(name, type letter) of every symbol nm lists in path; [] when nm cannot read it."""
    command = ["nm", "-P"] + (["-D", "--defined-only"] if dynamic else []) + [str(path)]
    done = subprocess.run(command, capture_output=True, text=True, errors="replace")
    found = []
    for line in done.stdout.splitlines():
        parts = line.split()
        if len(parts) >= 2 and not parts[0].endswith(":"):
            found.append((parts[0].split("@")[0], parts[1]))
    return found


@lru_cache(maxsize=None)
def system_symbols():
    """What the C and C++ run-time libraries define (a student defining one interposes it)."""
    found = set()
    for name in SYSTEM_LIBRARIES:
        done = subprocess.run(["gcc", f"-print-file-name={name}"], capture_output=True, text=True)
        path = done.stdout.strip()
        if path and path != name:
            found |= {s for s, kind in symbols(path, dynamic=True) if kind != "U"}
    return frozenset(found)


def harness_symbols(paths):
    """The strong and weak definitions of the harness's objects and archives."""
    found = set()
    for path in paths:
        found |= {s for s, kind in symbols(path) if kind not in "Uw v"}
    return frozenset(found) | system_symbols()


def demangle(names):
    if not names:
        return []
    done = subprocess.run(["c++filt"], input="\n".join(names), capture_output=True, text=True)
    return done.stdout.splitlines() if done.returncode == 0 else list(names)


def refusal(objects, harness):
    """One line saying why the objects (source name -> object path) are refused, or ""."""
    for source, obj in objects.items():
        listed = symbols(obj)
        if not listed:
            return f"`{source}`: its compiled object could not be read"
        defined = [(s, k) for s, k in listed if k not in "Uvw"]
        undefined = [s for s, k in listed if k in "Uvw"]
        for name, kind in defined:
            if name == "main":
                return f"`{source}` defines main(): the test program has its own"
            if name.startswith("_ZN7testing") or "gtest" in name.lower() or name.startswith("_ZNK7testing"):
                return f"`{source}` defines {demangle([name])[0]}, part of the test framework"
            if kind in STRONG_TYPES and name in harness:
                return f"`{source}` defines {demangle([name])[0]}, which the tests or libraries already define"
        for name in undefined:
            if name.startswith(("_ZN7testing", "_ZNK7testing", "_ZTIN7testing", "_ZTVN7testing")) or "gtest" in name.lower():
                return f"`{source}` uses the test framework ({demangle([name])[0].split('(')[0]})"
            if name in FORBIDDEN_CALLS:
                return f"`{source}` calls {name}(): lab code may not end the program, start processes or touch files"
            if name.startswith("_Z") and any(piece in name for piece in FORBIDDEN_CLASSES):
                return (f"`{source}` uses {demangle([name])[0].split('(')[0]}: "
                        "lab code may not write files")
            if name.startswith("_ZNSt10filesystem") and FORBIDDEN_FILESYSTEM.match(demangle([name])[0]):
                return f"`{source}` calls {demangle([name])[0].split('(')[0]}: lab code may not change files"
        code = subprocess.run(["objdump", "-d", "--no-show-raw-insn", str(obj)], capture_output=True,
                              text=True, errors="replace").stdout
        if RAW_SYSCALL.search(code):
            return f"`{source}` makes a raw system call (inline assembly): refused"
    return ""
