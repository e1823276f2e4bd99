"""How CMake links a target, read from CMake's public file API (cmake-file-api(7)), for the
tools that relink a lab's test program with other objects (class grading, the self-check, the
mutant and sheet-number checks). Not from CMakeFiles/<target>.dir/link.txt: that file is the
Makefile generator's private record, and Ninja has none.

The project's CMakeLists.txt asks for the replies (codemodel-v2, cache-v2) in every build
folder; a build configured before that is asked here, once, by re-running `cmake <build>`.
The command is put together as CMake's default rule for an executable writes it:
    <compiler> <flags> <objects> -o <program> <libraries>
with every relative path relative to `directory`, the folder the generator links in.
"""
import json
import os
import shlex
import subprocess
from dataclasses import dataclass, replace
from pathlib import Path

QUERIES = ("codemodel-v2", "cache-v2")


class LinkError(RuntimeError):
    """The build folder cannot say how the target is linked: one line for the user."""


@dataclass(frozen=True)
class LinkCommand:
    """One target's link command, split into its parts (each a tuple of command-line words)."""
    directory: Path  # where the command runs; relative words are relative to it
    compiler: str
    flags: tuple
    objects: tuple  # the target's own object files, in its sources' order
    output: str  # the word after -o
    libraries: tuple  # archives, shared libraries, -l and -L words, in link order

    def words(self):
        """The whole command, ready for subprocess.run(cwd=self.directory)."""
        return [self.compiler, *self.flags, *self.objects, "-o", self.output, *self.libraries]

    def path(self, word):
        """A path word of the command as an absolute path."""
        return (self.directory / word).resolve()

    def swap_library(self, archive, replacement):
        """The same command with the library at `archive` (a path) replaced by the words in
        `replacement`; LinkError if the command does not link it."""
        archive = Path(archive).resolve()
        for index, word in enumerate(self.libraries):
            if not word.startswith("-") and self.path(word) == archive:
                libraries = (*self.libraries[:index], *replacement, *self.libraries[index + 1:])
                return replace(self, libraries=libraries)
        raise LinkError(f"the link command does not name {archive}")


def link_command(build, target):
    """The LinkCommand of `target` in the configured Makefile or Ninja build folder `build`."""
    build = Path(build).resolve()
    try:
        index = reply_index(build)
        if index is None or not all(q in index.get("reply", {}) for q in QUERIES):
            request_replies(build)
            index = reply_index(build)
        if index is None or not all(q in index.get("reply", {}) for q in QUERIES):
            raise LinkError(f"{build}: CMake wrote no file API reply (cmake 3.14 or newer is needed)")
        return from_reply(build, index, target)
    except (OSError, ValueError, KeyError) as error:
        raise LinkError(f"{build}: CMake's file API reply cannot be read ({error})") from error


def reply_index(build):
    """The newest reply index (cmake-file-api(7): the lexicographically last index-*.json)."""
    indexes = sorted((build / ".cmake/api/v1/reply").glob("index-*.json"))
    return json.loads(indexes[-1].read_text(encoding="utf-8")) if indexes else None


def request_replies(build):
    if not (build / "CMakeCache.txt").is_file():
        raise LinkError(f"{build} is not a configured build folder (cmake --preset debug)")
    query = build / ".cmake/api/v1/query"
    query.mkdir(parents=True, exist_ok=True)
    for name in QUERIES:
        (query / name).touch()
    done = subprocess.run(["cmake", str(build)], capture_output=True, text=True, errors="replace")
    if done.returncode != 0:
        raise LinkError(f"re-running cmake in {build} for its file API reply failed: "
                        f"{(done.stderr.strip().splitlines() or ['no message'])[-1]}")


def from_reply(build, index, target):
    reply = build / ".cmake/api/v1/reply"

    def read(name):
        return json.loads((reply / name).read_text(encoding="utf-8"))

    generator = index["cmake"]["generator"]["name"]
    codemodel = read(index["reply"]["codemodel-v2"]["jsonFile"])
    entry = next((t for c in codemodel["configurations"] for t in c["targets"] if t["name"] == target), None)
    if entry is None:
        raise LinkError(f"{build}: CMake knows no target {target} (re-run cmake?)")
    model = read(entry["jsonFile"])
    if "link" not in model:
        raise LinkError(f"{target} is a {model['type']}, not linked")
    # Makefile generators link in the target's build folder, Ninja in the top one; the
    # reply's relative paths are relative to that folder.
    if "Makefiles" in generator:
        directory = build / model["paths"]["build"]
    elif generator.startswith("Ninja"):
        directory = build
    else:
        raise LinkError(f"{build}: a {generator} build; the lab tools relink with Makefile or Ninja builds")
    cache = read(index["reply"]["cache-v2"]["jsonFile"])
    language = model["link"]["language"]
    compiler = next((e["value"] for e in cache["entries"] if e["name"] == f"CMAKE_{language}_COMPILER"), None)
    if not compiler:
        raise LinkError(f"{build}: the CMake cache names no CMAKE_{language}_COMPILER")
    flags, libraries = [], []
    for fragment in model["link"]["commandFragments"]:
        (flags if fragment["role"] == "flags" else libraries).extend(shlex.split(fragment["fragment"]))
    return LinkCommand(directory=directory, compiler=compiler, flags=tuple(flags),
                       objects=tuple(objects_of(build, model, directory, Path(codemodel["paths"]["source"]))),
                       output=os.path.relpath(build / model["artifacts"][0]["path"], directory),
                       libraries=tuple(libraries))


def objects_of(build, model, directory, source_root):
    """The target's object files, found in compile_commands.json (CMAKE_EXPORT_COMPILE_COMMANDS):
    the outputs of its compiled sources in its own `<target>.dir` folder (a source can be
    compiled into two targets, e.g. a lab's tests and its exercise tests)."""
    commands = json.loads((build / "compile_commands.json").read_text(encoding="utf-8"))
    outputs = {}
    for command in commands:
        words = command.get("arguments") or shlex.split(command["command"])
        if "-o" not in words:
            continue  # (cl.exe names its object with /Fo: the tools relink GCC and Clang objects)
        output = Path(command["directory"]) / words[words.index("-o") + 1]
        if f"{model['name']}.dir" in output.parts:
            outputs[Path(command["directory"], command["file"]).resolve()] = output
    found = []
    for source in model["sources"]:
        if "compileGroupIndex" not in source:
            continue  # a header
        path = Path(source["path"])
        absolute = (path if path.is_absolute() else source_root / path).resolve()
        if absolute not in outputs:
            raise LinkError(f"{absolute}: not in {build}/compile_commands.json (re-run cmake)")
        found.append(os.path.relpath(outputs[absolute], directory))
    return found
