"""Every limit the grading engine puts on student code: the one home of these numbers.

The self-check (lab.py grade) and class grading (lab.py grade-class, Gradescope, GitHub
Classroom) use the same ones, so "passed" means the same everywhere.
"""

# One test process: CPU seconds. Every grading test is bounded by step counts and takes well
# under a second on the solution and on the starter; this is the last resort.
TEST_SECONDS = 5
# ...and its wall-clock guard. As for a compile, CPU time decides, so a machine busy grading
# a class (or CI's other stages) cannot turn a slow-but-correct test into "took too long" on
# one run and "passed" on the next; the guard only catches a test that waits (sleep, a read).
TEST_WALL_SECONDS = 3 * TEST_SECONDS
# One test process's address space (bytes): a test needs a few MB.
TEST_MEMORY = 1024 * 1024 * 1024
# Bytes one test process may print (stdout and stderr together) or write to any one file.
OUTPUT_BYTES = 1_000_000
# The private scratch folder of one test process (a tmpfs of this size, Linux class grading).
SCRATCH_BYTES = 64 * 1024 * 1024
# Processes and threads one test may have at once (a fork storm stops here).
TEST_PROCESSES = 64
# One compiler run: CPU seconds, address space, and the largest file it may write.
COMPILE_SECONDS = 60
# ...and its wall-clock guard. A compiler waits for nothing, so its CPU time decides: a
# machine busy grading a whole class must not turn a slow compile (a template bomb that
# g++ gives up on after 44 s of CPU) into "took too long" on one run and "did not build" on
# the next. The guard only catches what CPU time cannot see.
COMPILE_WALL_SECONDS = 3 * COMPILE_SECONDS
COMPILE_MEMORY = 2 * 1024 * 1024 * 1024
COMPILE_FILE_BYTES = 256 * 1024 * 1024
# Linking one lab's test program.
LINK_SECONDS = 60
# Listing the tests of a test program built from the instructor's code only (class grading,
# before any submission; the course's own checks of solutions and exercises). A program
# holding a student's code (the self-check) is listed under TEST_SECONDS and the test limits:
# the student's static initialisers run when it starts.
LIST_SECONDS = 60
# What one submission may hold once unpacked (a zip, a git repository or a folder): a lab's
# files are a few kilobytes, so this only stops a zip bomb or a stray video.
SUBMISSION_BYTES = 50 * 1000 * 1000
SUBMISSION_FILES = 5000
# Everything of one submission together (every lab): when it is used up, what is left is
# reported "not run: the submission used up its N s".
SUBMISSION_SECONDS = 300


def megabytes(count):
    """'1 MB' for 1_000_000, '64 MiB' for 64 * 2**20: how a limit is shown to people."""
    if count % (1024 * 1024 * 1024) == 0:
        return f"{count // (1024 * 1024 * 1024)} GiB"
    if count % (1024 * 1024) == 0:
        return f"{count // (1024 * 1024)} MiB"
    return f"{count / 1_000_000:g} MB"
