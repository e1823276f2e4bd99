# Cross-compiles Hitbox for 64-bit Windows with Debian's mingw-w64 (g++-mingw-w64-x86-64-posix,
# the "posix" threads flavour, which std::thread and std::mutex need). Used by
# scripts/ci-windows.sh; by hand:
#   cmake -S . -B build/mingw --toolchain framework/cmake/MingwW64Toolchain.cmake -DHITBOX_WITH_SFML=OFF
# There are no SFML binaries for mingw here, so only the SFML-free layers link.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
# Libraries, headers and CMake packages only from the mingw root; programs from the host.
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Self-contained .exe files: no libstdc++-6.dll or libwinpthread-1.dll to copy next to them.
# A DLL (BUILD_SHARED_LIBS) still needs them: scripts/wine-run.sh puts mingw's on wine's path.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++")
