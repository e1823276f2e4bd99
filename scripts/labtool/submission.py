"""One submission as handed in: its name, its files unpacked into a scratch folder (symbolic
links refused), and where in it each of a lab's student files is."""
import os
import subprocess
import zipfile
from pathlib import Path

from .limits import SUBMISSION_BYTES, SUBMISSION_FILES, megabytes

SKIPPED_FOLDERS = {".git", "build", ".vs", ".vscode", "out", "cmake-build-debug", "__MACOSX"}


class Refused(Exception):
    """The whole submission is refused; the message is the one line that says why."""


def submission_name(source):
    name = Path(source).name
    for suffix in (".zip", ".git", ".bundle"):
        if name.endswith(suffix):
            name = name[: -len(suffix)]
    return name


def printable_name(name):
    """A file name as one line of plain text: control characters and backquotes shown as
    escapes, so a name cannot add lines or formatting to the feedback."""
    return "".join(c if c.isprintable() and c != "`" else repr(c)[1:-1] if c != "`" else "\\x60"
                   for c in name)[:200]


def unpack(source, into):
    """The submission's files in a folder of their own; refuses symbolic links."""
    source = Path(source)
    files = into / "files"
    if source.is_file() and source.suffix == ".zip":
        with zipfile.ZipFile(source) as archive:
            members = archive.infolist()
            too_big(len(members), sum(m.file_size for m in members))  # before anything is written
            for member in members:
                if (member.external_attr >> 16) & 0o170000 == 0o120000:
                    raise Refused(f"refused: the zip holds a symbolic link ({printable_name(member.filename)})")
                target = (files / member.filename).resolve()
                if not str(target).startswith(str(files.resolve()) + os.sep):
                    raise Refused(f"refused: the zip writes outside its folder ({printable_name(member.filename)})")
                archive.extract(member, files)
    elif source.suffix == ".bundle" or (source.is_dir() and (source / "HEAD").is_file() and not (source / "labs").exists()):
        subprocess.run(["git", "clone", "--quiet", "--no-hardlinks", "--no-checkout", str(source), str(files)],
                       stderr=subprocess.DEVNULL, check=True)
        # The sizes the checkout would write, before it writes them.
        tree = subprocess.run(["git", "-C", str(files), "ls-tree", "-r", "-l", "HEAD"], capture_output=True,
                              text=True, errors="replace", check=True).stdout.splitlines()
        too_big(len(tree), sum(int(line.split()[3]) for line in tree if line.split()[3].isdigit()))
        subprocess.run(["git", "-C", str(files), "checkout", "--quiet"], stderr=subprocess.DEVNULL, check=True)
    elif source.is_dir():
        files = source
    else:
        raise Refused(f"not graded: {source.name} is not a folder, a .zip or a git repository")
    found, count, size = [], 0, 0
    for dirpath, dirnames, filenames in os.walk(files):
        for name in dirnames + filenames:
            path = Path(dirpath, name)
            if path.is_symlink():
                raise Refused(f"refused: the submission holds a symbolic link ({printable_name(path.relative_to(files).as_posix())})")
        count += len(filenames)
        size += sum(Path(dirpath, f).stat().st_size for f in filenames)
        too_big(count, size)
        dirnames[:] = [d for d in dirnames if d not in SKIPPED_FOLDERS and not d.startswith("build")]
        found += [Path(dirpath, f).relative_to(files).as_posix() for f in filenames]
    return files, sorted(found)


def too_big(count, size):
    """Refuses a submission of more than SUBMISSION_FILES files or SUBMISSION_BYTES."""
    if count > SUBMISSION_FILES or size > SUBMISSION_BYTES:
        files = f"{count} file{'' if count == 1 else 's'}"
        raise Refused(f"refused: the submission holds {files}, {megabytes(size)} once unpacked; at most "
                      f"{SUBMISSION_FILES} files, {megabytes(SUBMISSION_BYTES)} (a lab needs a few kilobytes)")


def find(lab, relative, files):
    """The student's copy of lab file `relative`: labs/NN_name/relative, NN_name/relative
    anywhere, or (a flat upload) the one file of that name."""
    folder = Path(lab.folder).name
    for wanted in (f"{lab.folder}/{relative}", f"{folder}/{relative}"):
        for candidate in files:
            if candidate == wanted or candidate.endswith("/" + wanted):
                return candidate
    same_name = [f for f in files if f == relative or f.endswith("/" + relative)]
    return same_name[0] if len(same_name) == 1 else None
