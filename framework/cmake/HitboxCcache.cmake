# Rebuilds of unchanged files come from ccache when it is installed (Debian: ccache), also
# from another checkout of the same sources: paths are taken relative to the source folder,
# and the build folder is left out of the hash (debug information may then name the first
# checkout that compiled a file).
# Without ccache nothing changes. HITBOX_CCACHE=OFF turns it off.
option(HITBOX_CCACHE "Use ccache when it is installed" ON)
find_program(HITBOX_CCACHE_PROGRAM ccache)
if(HITBOX_CCACHE AND HITBOX_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
    set(CMAKE_CXX_COMPILER_LAUNCHER
        "${CMAKE_COMMAND}" -E env "CCACHE_BASEDIR=${PROJECT_SOURCE_DIR}" CCACHE_NOHASHDIR=1
        "${HITBOX_CCACHE_PROGRAM}")
endif()
