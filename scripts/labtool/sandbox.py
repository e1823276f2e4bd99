"""The cage student code is built and run in for class grading (Linux, Debian's bubblewrap).

A caged process sees the system's programs and libraries read-only, the folders it is given
(read-only unless said otherwise), a private /tmp, and nothing else: no network, no other
processes, nothing of the instructor's tree, other students or the engine's own files. Test
programs also run as a user of their own (one per grading slot), so the process limit
counts only that slot's processes and a fork storm stops at it.
"""
import fcntl
import os
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path

from . import limits
from .procs import prlimit_prefix

SYSTEM_FOLDERS = ("/usr", "/etc/alternatives", "/etc/ld.so.cache")
FIRST_SANDBOX_USER = 61000  # grading slots run tests as users 61000, 61001, ... (no account needed)
SANDBOX_USERS = 1000


def claim_users(count):
    """count user ids no other grading run on this machine holds, each held by a lock file
    (kept open until this process ends): two runs at once never share a slot's user, so one
    never kills the other's processes."""
    held = []
    for user in range(FIRST_SANDBOX_USER, FIRST_SANDBOX_USER + SANDBOX_USERS):
        handle = open(Path(tempfile.gettempdir()) / f"hitbox-grading-user-{user}.lock", "a")
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            handle.close()
            continue
        held.append((user, handle))
        if len(held) == count:
            return held
    raise SandboxUnavailable("no free sandbox user ids (too many grading runs at once)")


class SandboxUnavailable(RuntimeError):
    pass


def ensure_bubblewrap():
    """bwrap, installed from Debian when missing (this script is run as root in CI and on
    a grading machine); raises SandboxUnavailable with the reason when it cannot be had."""
    if not shutil.which("bwrap"):
        if os.geteuid() == 0 and shutil.which("apt-get"):
            subprocess.run(["apt-get", "-o", "DPkg::Lock::Timeout=600", "install", "-y", "-q",
                            "--no-install-recommends", "bubblewrap"], stdout=subprocess.DEVNULL, check=False)
        if not shutil.which("bwrap"):
            raise SandboxUnavailable("bubblewrap (bwrap) is not installed: apt-get install bubblewrap")
    probe = subprocess.run(base_command([], []) + ["true"], capture_output=True, text=True)
    if probe.returncode != 0:
        raise SandboxUnavailable(f"bubblewrap cannot make a sandbox here: {probe.stderr.strip()}")


def base_command(read_only, writable, scratch_bytes=None, proc=True):
    """bwrap with the system read-only and the given folders bound at their own paths (or a
    (source, path) pair: source shown at path); proc:
    a /proc of the cage's own (tests get none: /proc/self/mem would let lab code read the
    process's memory as a file)."""
    command = ["bwrap", "--unshare-all", "--die-with-parent", "--new-session", "--dev", "/dev"]
    if proc:
        command += ["--proc", "/proc"]
    for folder in SYSTEM_FOLDERS:
        if os.path.exists(folder):
            command += ["--ro-bind", folder, folder]
    for name in ("bin", "sbin", "lib", "lib32", "lib64", "libx32"):
        target = os.path.join("/usr", name)
        if os.path.exists(target):
            command += ["--symlink", f"usr/{name}", f"/{name}"]
    if scratch_bytes:
        command += ["--size", str(scratch_bytes)]
    command += ["--tmpfs", "/tmp"]
    for folder in read_only:  # a folder, or (what to show, where)
        source, target = folder if isinstance(folder, tuple) else (folder, folder)
        command += ["--ro-bind", str(source), str(target)]
    for folder in writable:
        command += ["--bind", str(folder), str(folder)]
    return command


def compile_command(arguments, read_only, writable, cwd):
    """A compiler run caged: it reads only read_only, writes only writable."""
    return (prlimit_prefix(limits.COMPILE_MEMORY, limits.COMPILE_FILE_BYTES, limits.COMPILE_SECONDS)
            + base_command(read_only, writable) + ["--chdir", str(cwd), "--"] + list(arguments))


def test_command(program, arguments, report_dir, slot, read_only=()):
    """A test program run caged as the slot's own user: it sees its program, read_only (the
    course's assets), the folder its report goes in (fresh, made by the engine: see engine.py),
    a private scratch /tmp of SCRATCH_BYTES, and no /proc."""
    user = str(slot)
    return (["setpriv", f"--reuid={user}", f"--regid={user}", "--clear-groups", "--"]
            + prlimit_prefix(limits.TEST_MEMORY, limits.OUTPUT_BYTES, limits.TEST_SECONDS, limits.TEST_PROCESSES)
            + base_command([program, *read_only], [report_dir], limits.SCRATCH_BYTES, proc=False)
            + ["--chdir", "/tmp", "--setenv", "HOME", "/tmp", "--", str(program)] + list(arguments))


def processes_of_slot(slot):
    """Process ids still running as the slot's user (read from /proc)."""
    user, found = str(slot), []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                status = (entry / "status").read_text()
            except OSError:
                continue
            fields = dict(line.split(":", 1) for line in status.splitlines() if ":" in line)
            zombie = fields.get("State", "").strip().startswith("Z")  # already dead, not yet reaped
            if fields.get("Uid", "").split()[:1] == [user] and not zombie:
                found.append(int(entry.name))
    return found


def wait_until_slot_is_empty(slot, seconds=5.0):
    """Returns once no process of the slot's user is left (each one found is killed): only
    then is a test's report read. The cage's pid namespace ends them all; this waits for it."""
    deadline = time.monotonic() + seconds
    while True:
        left = processes_of_slot(slot)
        if not left:
            return True
        for pid in left:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        if time.monotonic() > deadline:
            return False
        time.sleep(0.01)


def give_to_slot(path, slot):
    """Makes path (a fresh folder) the slot user's, so the caged test can write its report."""
    os.chown(path, slot, slot)


def open_path_for_slot(path):
    """Lets another user reach path through its parent folders (search only, no listing)."""
    path = Path(path)
    for folder in [path.parent, *path.parent.parents]:
        mode = folder.stat().st_mode
        if not mode & 0o001:
            try:
                folder.chmod(mode | 0o001)
            except PermissionError:
                pass
        if str(folder) in ("/", "/tmp"):
            break
