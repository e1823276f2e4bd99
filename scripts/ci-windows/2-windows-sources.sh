# Sourced by scripts/ci-windows.sh, which sets out, linux_build, googletest and step():
# every other source compiled for Windows; no call MSVC deprecates and no system header
# outside the platform file.

step "2. every other source compiled for Windows (mingw, MSVC's deprecations, -Werror)"
# Against SFML 3's headers (what a Windows build downloads) when the Debian unstable root
# exists, else SFML 2's. The sources step 1 built for real are left out.
sfml=/var/cache/hitbox/sid-root/usr/include/SFML
[[ -f "$sfml/Config.hpp" ]] || sfml=/usr/include/SFML
mkdir -p "$out/sfml" && ln -sfn "$sfml" "$out/sfml/SFML"
label="SFML $(sed -n 's/^#define SFML_VERSION_MAJOR *\([0-9]*\).*/\1/p' "$sfml/Config.hpp")"
python3 scripts/compile-check.py mingw "$linux_build" "$PWD/$out/sfml" \
    "$googletest/googletest/include" "$googletest/googlemock/include" --skip "$out/mingw" | sed "s|^|  $label: |"
# mingw marks fewer calls deprecated than MSVC does (localtime, gmtime, ctime...): name them.
# Only framework/hitbox/platform/Platform.cpp may call them, or a POSIX environment call.
crt='(localtime|gmtime|ctime|asctime|strerror|getenv|strtok|v?sprintf|v?sscanf|v?fscanf|scanf'
crt+='|fopen|freopen|strn?cpy|strn?cat|mbstowcs|wcstombs|tmpnam|_?getpid|_?putenv|(un)?setenv)'
if git grep -nE "\b$crt\s*\(" -- '*.cpp' '*.h' ':!tests/course/week*' \
    ':!framework/hitbox/platform/Platform.cpp' | grep -vE '^[^:]*:[0-9]+:\s*//'; then
    echo "ci-windows: a C runtime call MSVC deprecates (C4996), outside the platform file:" \
         "call hitbox::platform (framework/hitbox/platform/Platform.h) instead" >&2
    exit 1
fi
if git grep -nE '#\s*include\s*<(unistd|dlfcn|pthread|fcntl|pwd|termios|windows|process)\.h>|#\s*include\s*<sys/' \
    -- '*.cpp' '*.h' ':!tests/course/week*' ':!framework/hitbox/platform/Platform.cpp'; then
    echo "ci-windows: a system header outside framework/hitbox/platform/Platform.cpp" >&2
    exit 1
fi
# A per-file optimisation pragma can break another file's code under GCC's inter-procedural
# register allocation (a mingw Release build once crashed so): the build type decides.
if git grep -nE '^\s*#\s*pragma\s+GCC\s+optimize' -- '*.cpp' '*.h'; then
    echo "ci-windows: #pragma GCC optimize: leave optimisation to the build type" >&2
    exit 1
fi
echo "  no call MSVC deprecates and no system header outside framework/hitbox/platform/Platform.cpp"
