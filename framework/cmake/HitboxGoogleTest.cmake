# GoogleTest for the tests: the system's (Debian's libgtest-dev, Homebrew's googletest, vcpkg's
# when CMAKE_TOOLCHAIN_FILE points at vcpkg), else a pinned release downloaded and built once,
# the way GoogleTest's own quick start does (google.github.io/googletest/quickstart-cmake.html).
# Offline, point FETCHCONTENT_SOURCE_DIR_GOOGLETEST at a copy of its sources (Debian's
# `googletest` package puts them in /usr/src/googletest). -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON
# skips the system's copy, to try the download path. One line says which GoogleTest is used.
find_package(GTest QUIET)
if(GTest_FOUND)
    message(STATUS "Hitbox: using the system's GoogleTest ${GTest_VERSION}")
    return()
endif()

set(HITBOX_GOOGLETEST_VERSION 1.15.2)
include(FetchContent)
include(HitboxFetchOptions)
hitbox_fetch_options(fetch_options)
FetchContent_Declare(googletest
    GIT_REPOSITORY https://github.com/google/googletest.git
    GIT_TAG v${HITBOX_GOOGLETEST_VERSION}
    GIT_SHALLOW ON
    ${fetch_options})
# MSVC: link the C runtime the way the rest of the build does (/MD), as GoogleTest's quick
# start says; no install rules, no gmock (Hitbox's tests do not use it).
set(gtest_force_shared_crt ON CACHE BOOL "" FORCE)
set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
FetchContent_MakeAvailable(googletest)
if(FETCHCONTENT_SOURCE_DIR_GOOGLETEST)
    message(STATUS "Hitbox: using GoogleTest from ${FETCHCONTENT_SOURCE_DIR_GOOGLETEST}")
else()
    message(STATUS "Hitbox: using downloaded GoogleTest ${HITBOX_GOOGLETEST_VERSION}")
endif()
