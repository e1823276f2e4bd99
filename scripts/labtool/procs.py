"""Running one process of student code (a compiler on their source, or a test program) with
limits, and saying what stopped it. The process gets a session (process group) of its own;
when it ends or its time is up the whole group is killed, so nothing it started outlives it."""
import os
import signal
import subprocess
import time
from dataclasses import dataclass

from .limits import megabytes

POSIX = os.name == "posix"


@dataclass
class Outcome:
    status: int  # exit status; negative: killed by that signal
    seconds: float
    timed_out: bool
    output: str  # what it printed (stdout and stderr together), at most the cap
    output_bytes: int

    def signal_name(self):
        try:
            return signal.Signals(-self.status).name
        except ValueError:
            return f"signal {-self.status}"


def _limits(memory, file_bytes, cpu_seconds):
    """Sets the limits in the child before it runs (POSIX; single-threaded callers only)."""
    import resource

    def apply():
        for kind, value in ((resource.RLIMIT_AS, memory), (resource.RLIMIT_FSIZE, file_bytes),
                            (resource.RLIMIT_CPU, cpu_seconds), (resource.RLIMIT_CORE, 0)):
            if value:
                try:
                    resource.setrlimit(kind, (value, value))
                except (ValueError, OSError):
                    pass  # (macOS refuses some; the wall-clock limit still holds)
    return apply


def prlimit_prefix(memory, file_bytes, cpu_seconds, processes=None):
    """The same limits as a command prefix (Linux's prlimit): safe from threads."""
    prefix = ["prlimit", f"--as={memory}", f"--fsize={file_bytes}", "--core=0"]
    if cpu_seconds:
        prefix.append(f"--cpu={cpu_seconds}")
    if processes:
        prefix.append(f"--nproc={processes}")
    return prefix + ["--"]


def kill_group(process):
    if POSIX:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
    else:
        subprocess.run(["taskkill", "/F", "/T", "/PID", str(process.pid)], capture_output=True)
    try:
        process.kill()
    except OSError:
        pass


def run_limited(command, output_path, seconds, cwd=None, env=None, memory=0, file_bytes=0,
                cpu_seconds=0, set_limits_here=False, pass_fds=()):
    """Runs command with its output (stdout + stderr) in output_path, killed with its whole
    process group after `seconds`. With set_limits_here the POSIX limits are set in the child
    (only for single-threaded callers; threaded callers put prlimit_prefix() in front).
    pass_fds: descriptors the command inherits (POSIX)."""
    extra = {}
    if POSIX:
        extra["start_new_session"] = True
        extra["pass_fds"] = tuple(pass_fds)
        if set_limits_here:
            extra["preexec_fn"] = _limits(memory, file_bytes, cpu_seconds)
    else:
        extra["creationflags"] = subprocess.CREATE_NEW_PROCESS_GROUP
    started = time.monotonic()
    with open(output_path, "wb") as output:
        process = subprocess.Popen(command, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=output,
                                   stderr=subprocess.STDOUT, **extra)
        timed_out = False
        try:
            process.wait(timeout=seconds)
        except subprocess.TimeoutExpired:
            timed_out = True
        except BaseException:
            kill_group(process)  # Ctrl-C: nothing of it may keep running
            process.wait()
            raise
        finally:
            if process.poll() is None or POSIX:
                kill_group(process)  # everything it started, too
            process.wait()
    size = os.path.getsize(output_path)
    with open(output_path, "rb") as output:
        text = output.read(file_bytes or 1_000_000).decode("utf-8", errors="replace")
    return Outcome(process.returncode, time.monotonic() - started, timed_out, text, size)


def why_stopped(outcome, seconds, output_cap, what="the test", wall_seconds=None):
    """One line saying what a limit did, or "" when none stopped it. `seconds` is the CPU
    limit; `wall_seconds` the wall-clock guard when it is longer (by default the same)."""
    wall = wall_seconds or seconds
    # A SIGKILL at or after the time limit is the limit's doing (the CPU limit's hard stop, or
    # the group killed as the wait gave up), not a crash: the same hang reads the same way.
    # (A process cannot use more CPU seconds than wall-clock seconds, so an earlier SIGKILL
    # is not the CPU limit's.)
    killed_late = outcome.status < 0 and outcome.signal_name() == "SIGKILL" and outcome.seconds >= seconds
    if outcome.timed_out or (killed_late and wall == seconds):
        return f"{what} took longer than {wall:g} s (an endless loop?)"
    if killed_late:
        return f"{what} used more than {seconds:g} s of CPU time"
    if outcome.status < 0:
        name = outcome.signal_name()
        if name == "SIGXFSZ":
            if outcome.output_bytes >= output_cap:
                return f"{what} printed more than {megabytes(output_cap)}"
            return f"{what} wrote a file bigger than {megabytes(output_cap)}"
        if name in ("SIGXCPU",):
            return f"{what} used more than {seconds:g} s of CPU time"
        return f"crashed: {name}"
    if outcome.status >= 0xC0000000:  # Windows: an exception code (0xC0000005: access violation)
        return f"crashed: Windows exception 0x{outcome.status:08X}"
    return ""


