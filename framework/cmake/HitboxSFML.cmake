# Find SFML 2.5 or 2.6; with HITBOX_FETCH_SFML=ON, build SFML 2.6 from source when it is
# not installed (for Windows and macOS machines without a system SFML).
find_package(SFML 2.5 COMPONENTS graphics window system audio QUIET)
if(NOT SFML_FOUND)
    if(HITBOX_FETCH_SFML)
        include(FetchContent)
        FetchContent_Declare(SFML
            GIT_REPOSITORY https://github.com/SFML/SFML.git
            GIT_TAG 2.6.1)
        set(SFML_BUILD_NETWORK OFF CACHE BOOL "" FORCE)
        FetchContent_MakeAvailable(SFML)
    else()
        message(FATAL_ERROR
            "SFML 2.5 or 2.6 was not found.\n"
            "  Debian/Ubuntu: run ./scripts/install-deps.sh (or: sudo apt-get install libsfml-dev)\n"
            "  Windows/macOS: configure with -DHITBOX_FETCH_SFML=ON to download and build SFML 2.6")
    endif()
endif()
