"""The lab list: which labs a tree has, their folders, the files students edit, their tasks."""
import re
from pathlib import Path

from . import markers

REPO = Path(__file__).resolve().parents[2]
LAB_CALL = re.compile(r"^\s*hitbox_add_lab\(\s*([A-Za-z0-9_]+)", re.M)
# In a handout the markers are gone, so make-handout writes the list of student files here.
STUDENT_FILES_LIST = Path("scripts") / "labtool" / "student-files.txt"


class BadInput(ValueError):
    """A mistake in what the user asked for: one line, exit status 2."""


class Lab:
    """One lab: name (lab02_bouncing_balls), folder (labs/02_bouncing_balls, relative to
    the tree), the files a student edits (relative to the folder) and its task numbers."""

    def __init__(self, repo, name, folder):
        self.repo, self.name, self.folder = Path(repo), name, folder
        self.number = Path(folder).name.split("_", 1)[0]
        self.student_files = student_files(self.repo, folder)

    def tasks(self):
        """The task numbers the sources mark (solution or exercise), sorted."""
        found = set()
        for relative in self.student_files:
            path = self.repo / self.folder / relative
            if path.is_file():
                found |= markers.tasks_in_text(path.read_text(encoding="utf-8", errors="replace"))
        return sorted(found)

    def visible_tests(self):
        """Suite.Name of every test the lab's grading-test sources define (not disabled)."""
        found = []
        for source in sorted((self.repo / "tests" / "labs" / Path(self.folder).name).glob("*.cpp")):
            text = source.read_text(encoding="utf-8", errors="replace")
            found += [f"{s}.{n}" for s, n in re.findall(r"^\s*TEST\(\s*(\w+)\s*,\s*(\w+)\s*\)", text, re.M)
                      if not s.startswith("DISABLED_") and not n.startswith("DISABLED_")]
        return found

    def hidden_tests(self):
        """Suite.Name of every test in the instructor's hidden variants (never in a handout)."""
        found = set()
        for source in sorted((self.repo / "tests" / "labs-hidden" / Path(self.folder).name).glob("*.cpp")):
            text = source.read_text(encoding="utf-8", errors="replace")
            found |= {f"{s}.{n}" for s, n in re.findall(r"^\s*TEST(?:_F)?\(\s*(\w+)\s*,\s*(\w+)\s*\)", text, re.M)}
        return found


def is_handout(repo=REPO):
    return (Path(repo) / "framework" / "cmake" / "HitboxHandout.cmake").exists()


def student_files(repo, folder):
    """The files a student edits: the lab's sources with a task marker in the solution."""
    listed = Path(repo) / STUDENT_FILES_LIST
    if listed.exists():
        prefix = folder.rstrip("/") + "/"
        return [line[len(prefix):] for line in listed.read_text(encoding="utf-8").split() if line.startswith(prefix)]
    found = []
    for path in sorted((Path(repo) / folder).rglob("*")):
        if path.suffix in markers.SOURCE_SUFFIXES and path.is_file():
            if markers.tasks_in_text(path.read_text(encoding="utf-8", errors="replace")):
                found.append(path.relative_to(Path(repo) / folder).as_posix())
    return found


def all_labs(repo=REPO):
    labs = []
    for cmakelists in sorted(Path(repo).glob("labs/[0-9][0-9]_*/CMakeLists.txt")):
        match = LAB_CALL.search(cmakelists.read_text(encoding="utf-8"))
        if match:
            labs.append(Lab(repo, match.group(1), cmakelists.parent.relative_to(repo).as_posix()))
    return labs


def find_lab(given, labs):
    """The lab called given: '02', '2', '02_bouncing_balls', 'lab02_bouncing_balls' or 'labs/02_...'."""
    wanted = given.strip().rstrip("/\\").replace("\\", "/").split("/")[-1]
    for lab in labs:
        folder = Path(lab.folder).name
        if wanted in (lab.name, folder, lab.number) or (wanted.isdigit() and int(wanted) == int(lab.number)):
            return lab
    raise BadInput(f"no lab called '{given}'; the labs here: {' '.join(l.number for l in labs) or 'none'}"
                   f" (e.g. {labs[0].number if labs else '02'} or {labs[0].name if labs else 'lab02_bouncing_balls'})")
