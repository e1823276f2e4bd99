# Sourced by scripts/ci-windows.sh, which sets out, linux_build, googletest and step():
# the presets, and a clean clone built and tested through them with a multi-config generator.

step "4. the presets: schema, Windows-only and Linux-only ones, a multi-config run"
# Visual Studio 2022 reads presets up to schema version 5 (learn.microsoft.com, "Configure
# and build with CMake Presets in Visual Studio").
python3 -c 'import json, sys; version = json.load(open("CMakePresets.json"))["version"]
sys.exit(f"CMakePresets.json: schema version {version}; Visual Studio 2022 reads up to 5" if version > 5 else 0)'
# What Visual Studio lists on Windows: CMake's own answer on a copy where this host plays Windows.
mkdir -p "$out/presets-on-windows"
sed 's/"Windows"/"Linux"/g' CMakePresets.json >"$out/presets-on-windows/CMakePresets.json"
listed=$(cd "$out/presets-on-windows" && cmake --list-presets=all | grep -oE '^ +"[a-z-]+"' | tr -d ' "' | sort -u | tr '\n' ' ')
if [[ "$listed" != "windows windows-release " ]]; then
    echo "ci-windows: on Windows the presets listed would be: $listed (expected windows windows-release)" >&2
    exit 1
fi
echo "  on Windows only these presets show: $listed"
# Shell scripts stay LF on a Windows checkout (.gitattributes).
if git ls-files '*.sh' | xargs git check-attr eol -- | grep -v ': eol: lf$'; then
    echo "ci-windows: these scripts would get CRLF line endings on Windows (.gitattributes)" >&2
    exit 1
fi
# A clean clone through the presets with a multi-config generator: every test runs.
git clone -q . "$out/clone"
(
    cd "$out/clone"
    export CMAKE_GENERATOR="Ninja Multi-Config"
    cmake --preset debug >../clone-configure.log
    cmake --build --preset debug >../clone-build.log
    ctest --preset debug >../clone-ctest.log 2>&1 || true
)
if grep -q "Not Run" "$out/clone-ctest.log" || ! grep -q "100% tests passed" "$out/clone-ctest.log"; then
    grep -E "Not Run|Failed|tests passed" "$out/clone-ctest.log" | tail -n 20 >&2
    echo "ci-windows: the presets under Ninja Multi-Config do not run every test; see $out/clone-ctest.log" >&2
    exit 1
fi
grep "tests passed" "$out/clone-ctest.log" | sed 's/^/  Ninja Multi-Config: /'
