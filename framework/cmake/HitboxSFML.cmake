# Finds SFML and gives the rest of the build one target, `hitbox_sfml_library`, that links it.
#
# With no option: the system's SFML 3, else the system's SFML 2.6 or 2.5.
# -DHITBOX_SFML_MAJOR=2 or =3 forces a major version (old course labs need 2, new ones 3).
# Where the system has no usable SFML (Windows, macOS without Homebrew, a Linux with the wrong
# major version), CMake downloads and builds a pinned SFML release once, the way SFML's own
# CMake template does. One line says which SFML the build chose.
set(HITBOX_SFML_MAJOR "" CACHE STRING "SFML major version to use: 2, 3, or empty for the newest installed")
set_property(CACHE HITBOX_SFML_MAJOR PROPERTY STRINGS "" 2 3)
if(NOT HITBOX_SFML_MAJOR MATCHES "^[23]?$")
    message(FATAL_ERROR "HITBOX_SFML_MAJOR must be 2, 3 or empty, not '${HITBOX_SFML_MAJOR}'")
endif()

# SFML 3 names its components and targets with capitals (SFML::Graphics); 2.x does not
# (sfml-graphics). Everything else in the build links hitbox_sfml_library and never sees the names.
add_library(hitbox_sfml_library INTERFACE)
if(NOT HITBOX_SFML_MAJOR STREQUAL "2")
    find_package(SFML 3 COMPONENTS Graphics Audio QUIET)
endif()
if(NOT SFML_FOUND AND NOT HITBOX_SFML_MAJOR STREQUAL "3")
    find_package(SFML 2.5 COMPONENTS graphics window system audio QUIET)
endif()

if(SFML_FOUND)
    set(how "the system's")
else()
    # SFML's CMake template (github.com/SFML/cmake-sfml-project). Not tried on the project's
    # machines, which cannot reach GitHub.
    if(HITBOX_SFML_MAJOR STREQUAL "2")
        set(SFML_VERSION 2.6.2)
    else()
        set(SFML_VERSION 3.0.2)
    endif()
    set(how "downloaded")
    include(FetchContent)
    # As SFML's CMake template does: SYSTEM and EXCLUDE_FROM_ALL where this CMake has them.
    include(HitboxFetchOptions)
    hitbox_fetch_options(fetch_options)
    FetchContent_Declare(SFML
        GIT_REPOSITORY https://github.com/SFML/SFML.git
        GIT_TAG ${SFML_VERSION}
        GIT_SHALLOW ON
        ${fetch_options})
    set(SFML_BUILD_NETWORK OFF CACHE BOOL "" FORCE)
    if(UNIX AND NOT APPLE)
        # freetype, FLAC, Vorbis, OpenGL, X11 from the system (./scripts/install-deps.sh).
        set(SFML_USE_SYSTEM_DEPS ON CACHE BOOL "" FORCE)
    endif()
    FetchContent_MakeAvailable(SFML)
endif()

if(SFML_VERSION VERSION_GREATER_EQUAL 3)
    target_link_libraries(hitbox_sfml_library INTERFACE SFML::Graphics SFML::Audio)
else()
    target_link_libraries(hitbox_sfml_library INTERFACE sfml-graphics sfml-audio)
endif()
message(STATUS "Hitbox: using ${how} SFML ${SFML_VERSION} (choose with -DHITBOX_SFML_MAJOR=2 or 3)")

# SFML 2 loads OpenAL at run time: its openal32.dll ships in SFML's source tree (extlibs/bin)
# and is copied next to every program (hitbox_copy_runtime_dlls, HitboxWarnings.cmake), the
# way SFML's CMake template does.
set(HITBOX_OPENAL_DLL "")
if(WIN32 AND SFML_VERSION VERSION_LESS 3 AND DEFINED SFML_SOURCE_DIR)
    if(CMAKE_SIZEOF_VOID_P EQUAL 8)
        set(HITBOX_OPENAL_DLL "${SFML_SOURCE_DIR}/extlibs/bin/x64/openal32.dll")
    else()
        set(HITBOX_OPENAL_DLL "${SFML_SOURCE_DIR}/extlibs/bin/x86/openal32.dll")
    endif()
endif()
