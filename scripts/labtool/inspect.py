"""Reads a submission's compiled objects (nm, objdump) and refuses, with one line, code that
could decide its own verdict: a lab's code computes positions and collisions, it never needs
to own the program, the test framework, files or other processes.

Refused when a student object
- defines main, anything of GoogleTest (testing::, gtest), or a strong symbol the harness
  already defines (the tests, the lab's other files, the framework, GoogleTest, the C and C++
  libraries): replacing one changes what the tests see;
- calls a function of the C library that is not on its short list of computing functions
  (maths, memory, text, printing, time, threads: C_LIBRARY_ALLOWED): a list of what may be
  called, not of what may not, so a function nobody thought of (dlvsym, _Fork, ...) is
  refused too; or std::ofstream, std::fstream, or std::filesystem calls that change files or
  list folders (reading a file, as lab 9's level loader does, is allowed; a std::filebuf
  opened for writing, which that reading shares its function with, can write only in the
  test's private /tmp);
- defines a name of GoogleTest (or of anything made of its types, such as a std::vector of
  its results) or of the C library, even weakly: the program's own copy of such a name can
  be the one every caller gets;
- runs code before the test program's own start-up or in an order of its own (a constructor
  priority, .preinit_array, .init or .fini code, an ifunc resolver): the program takes its
  report's path from the grader first (TestMain.cpp);
- contains a raw system call instruction.
Comments, strings and the student's own macros never matter: only compiled code is read.
"""
import re
import subprocess
import sys
from functools import lru_cache
from pathlib import Path

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
# std::filesystem operations that change files or folders or list folders (status, exists,
# file_size, path and the current_path() getter are fine: lab 9 uses some).
FORBIDDEN_FILESYSTEM = re.compile(r"^std::filesystem::(__cxx11::)?(remove|remove_all|rename|copy|copy_file|"
                                  r"copy_symlink|create_\w+|resize_file|permissions|"
                                  r"current_path(\[abi:cxx11\])?\(std::filesystem|"
                                  r"last_write_time|directory_iterator|recursive_directory_iterator)\b")
# The C library functions lab code may call (the C library is where the operating system's
# calls live): exact names, then families by pattern. Everything libm defines is allowed too.
C_LIBRARY_ALLOWED = {
    "malloc", "calloc", "realloc", "free", "aligned_alloc", "posix_memalign",
    "abs", "labs", "llabs", "div", "ldiv", "lldiv", "atoi", "atol", "atoll", "atof",
    "rand", "srand", "rand_r", "random", "srandom", "drand48", "srand48", "lrand48", "qsort", "bsearch",
    "abort", "getenv", "secure_getenv", "time", "clock", "clock_gettime", "gettimeofday", "difftime",
    "mktime", "localtime", "localtime_r", "gmtime", "gmtime_r", "strftime", "sleep", "usleep", "nanosleep",
    "printf", "vprintf", "puts", "putchar", "fputs", "fputc", "putc", "fprintf", "vfprintf", "fwrite",
    "fflush", "sprintf", "snprintf", "vsprintf", "vsnprintf", "sscanf", "vsscanf", "getchar", "fgets",
    "stdin", "stdout", "stderr", "perror", "__errno_location", "__assert_fail", "__stack_chk_fail",
    "__cxa_atexit", "__cxa_finalize", "__cxa_thread_atexit_impl", "__dso_handle", "__tls_get_addr",
    "__libc_single_threaded", "sched_yield", "get_nprocs", "sysconf", "frexp", "ldexp", "modf",
    "copysign", "copysignf", "finite", "finitef", "isinf", "isinff", "isnan", "isnanf", "__isnan", "__isnanf",
    "__isinf", "__isinff", "__finite", "__finitef", "ctime", "ctime_r", "asctime", "asctime_r",
    "fclose", "fgetc", "getc", "fread", "feof", "ferror", "clearerr", "fseek", "ftell", "rewind", "ungetc",
    "setvbuf", "setbuf", "setlocale", "getpid",
}
C_LIBRARY_ALLOWED_FAMILIES = re.compile(
    r"^(_*(mem|str|wcs|wmem|mb|wc)[a-z0-9_]*|__\w*(printf|mem\w*|str\w*|stp\w*|wcs\w*|wmem\w*)_chk|is(alnum|alpha|blank|cntrl|digit|graph|lower|print|punct|"
    r"space|upper|xdigit)|to(upper|lower)|__ctype_\w+|__isoc\d\d_\w*scanf|__isoc\d\d_strto\w+|"
    r"pthread_(create|join|detach|self|equal|once|key_\w+|getspecific|setspecific|mutex\w*|cond\w*|"
    r"rwlock\w*|attr\w*|spin\w*))$")
C_LIBRARIES = ("libc.so.6",)
MATH_LIBRARIES = ("libm.so.6",)
# No student object may define a name these define: the program's own copy would be used
# everywhere, by GoogleTest too (a home-made fopen would see the report's path).
C_RUNTIME = ("libc.so.6", "libm.so.6", "libgcc_s.so.1", "libpthread.so.0", "libdl.so.2")
# Sections whose code runs before the program's own start-up (or in an order of its own),
# refused in a student object: everything but the plain .init_array of ordinary constructors.
EARLY_SECTIONS = re.compile(r"^\.(init|fini|preinit_array.*|init_array\..*|fini_array\..*|ctors.*|dtors.*)$")
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


def library_path(name):
    done = subprocess.run(["gcc", f"-print-file-name={name}"], capture_output=True, text=True)
    path = done.stdout.strip()
    return path if path and path != name else None


@lru_cache(maxsize=None)
def defined_by(names):
    """What the shared libraries `names` (a tuple) define."""
    found = set()
    for name in names:
        path = library_path(name)
        if path:
            found |= {s for s, kind in symbols(path, dynamic=True) if kind != "U"}
    return frozenset(found)


def c_library_refuses(name):
    """True for a C library function lab code may not call (see C_LIBRARY_ALLOWED)."""
    if sys.platform.startswith("linux") and not defined_by(C_LIBRARIES):
        raise RuntimeError("the grader cannot find libc.so.6 (gcc -print-file-name), so it cannot "
                           "check which C library functions lab code calls")
    if name not in defined_by(C_LIBRARIES) or name in defined_by(MATH_LIBRARIES):
        return False
    if name.startswith("memfd") or "dprintf" in name:  # a file in memory; printing to any descriptor
        return True
    return name not in C_LIBRARY_ALLOWED and not C_LIBRARY_ALLOWED_FAMILIES.match(name)


def weak_outside_groups(obj):
    """Names obj defines weakly outside a COMDAT group: what `__attribute__((weak))` or
    `#pragma weak` make. The compiler's own weak copies (inline functions, templates) each sit
    in a group; a hand-made weak definition exists only to be chosen over someone else's."""
    groups = subprocess.run(["readelf", "-gW", str(obj)], capture_output=True, text=True, errors="replace").stdout
    grouped = set(re.findall(r"^\s*\[\s*(\d+)\]\s+\S", groups, flags=re.M))
    table = subprocess.run(["readelf", "-sW", str(obj)], capture_output=True, text=True, errors="replace").stdout
    found = []
    for line in table.splitlines():
        parts = line.split()
        if len(parts) >= 8 and parts[4] == "WEAK" and parts[6].isdigit() and parts[6] not in grouped:
            found.append(parts[7])
    return found


@lru_cache(maxsize=None)
def start_up_names():
    """Every name the C run-time's start-up files define or call (crt1.o, crti.o, crtbegin.o,
    ...): a student's definition of one (__gmon_start__) would run before the program's own
    start-up."""
    found = set()
    for name in ("crt1.o", "Scrt1.o", "crti.o", "crtn.o", "crtbegin.o", "crtbeginS.o", "crtend.o", "crtendS.o"):
        path = library_path(name)
        if path:
            found |= {s for s, kind in symbols(path) if kind.isupper() or kind in "wv"}  # not local ones
    return frozenset(found)


def test_framework(name, readable):
    """True for a symbol of GoogleTest, or of anything made of its types."""
    return "gtest" in name.lower() or "testing::" in readable


def early_start_up(obj):
    """Why obj's code would run before the program's start-up, or ""."""
    done = subprocess.run(["objdump", "-h", str(obj)], capture_output=True, text=True, errors="replace")
    for line in done.stdout.splitlines():
        parts = line.split()
        if len(parts) > 1 and parts[0].isdigit() and EARLY_SECTIONS.match(parts[1]):
            return (f"asks to run code before or after the test program's own start-up ({parts[1]}: "
                    "a constructor priority, or assembly placed in start-up code)")
    return ""


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
    """The strong and weak definitions of the harness's objects, archives and shared libraries."""
    found = set()
    for path in paths:
        shared = ".so" in Path(path).name
        found |= {s for s, kind in symbols(path, dynamic=shared) if kind not in "Uw v"}
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
        early = early_start_up(obj)
        if early or any(kind == "i" for _, kind in listed):
            return f"`{source}` {early or 'has an ifunc resolver, which runs before the test program starts'}"
        weak = weak_outside_groups(obj)
        if weak:
            return (f"`{source}` makes {demangle(weak[:1])[0].split('(')[0][:120]} weak "
                    "(__attribute__((weak))): a weak definition exists to replace another one")
        readable = dict(zip([n for n, _ in listed], demangle([n for n, _ in listed])))
        shown = {n: r.split("(")[0][:120] for n, r in readable.items()}  # for one line
        for name, kind in defined:
            if name == "main":
                return f"`{source}` defines main(): the test program has its own"
            # Weak definitions too: the linker may keep either copy (a weak
            # std::vector<testing::TestPartResult> member once threw away every failure).
            if test_framework(name, readable.get(name, name)):
                return f"`{source}` defines {shown.get(name, name)}, part of the test framework"
            if kind in STRONG_TYPES and name in harness:
                return f"`{source}` defines {shown.get(name, name)}, which the tests or libraries already define"
            if name in defined_by(C_RUNTIME):  # a definition in the program wins over the library's
                return f"`{source}` defines {name}, a function of the C library"
            if kind.isupper() and name in start_up_names():
                return f"`{source}` defines {name}, which the program's start-up code calls"
        for name in undefined:
            if test_framework(name, readable.get(name, name)):
                return f"`{source}` uses the test framework ({shown.get(name, name)})"
            if name in FORBIDDEN_CALLS:
                return f"`{source}` calls {name}(): lab code may not end the program, start processes or touch files"
            if c_library_refuses(name):
                return (f"`{source}` calls {name}(), which lab code may not: of the C library it may use "
                        "maths, memory, text, printing, time and threads only")
            if name.startswith("_Z") and any(piece in name for piece in FORBIDDEN_CLASSES):
                return (f"`{source}` uses {demangle([name])[0].split('(')[0]}: "
                        "lab code may not write files")
            if name.startswith("_ZNSt10filesystem") and FORBIDDEN_FILESYSTEM.match(demangle([name])[0]):
                return f"`{source}` calls {demangle([name])[0].split('(')[0]}: lab code may not change files or list folders"
        code = subprocess.run(["objdump", "-d", "--no-show-raw-insn", str(obj)], capture_output=True,
                              text=True, errors="replace").stdout
        if RAW_SYSCALL.search(code):
            return f"`{source}` makes a raw system call (inline assembly): refused"
    return ""
