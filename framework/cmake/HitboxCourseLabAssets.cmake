# Makes the folder a course lab runs from: the lab folder's pictures, fonts, sounds and data
# files, linked (or copied where links are not allowed) into RUN_DIR, plus a second name for
# every file the lab's code names with different letter case.
#
# Windows (and macOS) ignore letter case, so a lab that loads "gfx/Beach_ball.png" while the
# file is gfx/Beach_Ball.png works there and, on Linux, silently draws a white box. The file
# names the code uses are read from its string literals; each one that names no file as
# written but does when case is ignored gets a link of that spelling. (A name put together
# at run time, "gfx/" + name + ".png", is not seen: give that file the right case.)
#
# Usage: cmake -DLAB_DIR=<lab> -DRUN_DIR=<build>/course_lab_run "-DSOURCES=<file>;..."
#              -P HitboxCourseLabAssets.cmake
# The lab folder itself is never changed. Run at every build: new assets are picked up.
cmake_minimum_required(VERSION 3.16)

file(MAKE_DIRECTORY "${RUN_DIR}")

# Everything in the lab folder except its code, the parts Hitbox replaces, Visual Studio's
# files and build output.
file(GLOB_RECURSE lab_files RELATIVE "${LAB_DIR}" LIST_DIRECTORIES false "${LAB_DIR}/*")
list(FILTER lab_files EXCLUDE REGEX "^(Framework|SFML|x64|x86|Debug|Release|\\.vs|\\.git)/")
list(FILTER lab_files EXCLUDE REGEX "(^|/)(CMakeFiles|course_lab_[a-z]+|_deps|build[^/]*)/")
list(FILTER lab_files EXCLUDE REGEX "\\.(cpp|h|hpp|vcxproj|filters|user|sln)$")

function(link_asset relative_link lab_file)
    set(link "${RUN_DIR}/${relative_link}")
    if(NOT EXISTS "${link}")
        get_filename_component(link_folder "${link}" DIRECTORY)
        file(MAKE_DIRECTORY "${link_folder}")
        file(CREATE_LINK "${LAB_DIR}/${lab_file}" "${link}" SYMBOLIC COPY_ON_ERROR)
        if(NOT relative_link STREQUAL lab_file)
            message(STATUS "Course lab: \"${relative_link}\" is ${lab_file} (letter case differs)")
        endif()
    endif()
endfunction()

set(lower_names "")
foreach(lab_file IN LISTS lab_files)
    link_asset("${lab_file}" "${lab_file}")
    string(TOLOWER "${lab_file}" lower_name)
    list(APPEND lower_names "${lower_name}")
endforeach()

# File names in the code: string literals ending in a dot and an extension.
set(named_files "")
foreach(source IN LISTS SOURCES)
    # file(STRINGS) reads UTF-16 sources too (it follows the byte-order mark).
    file(STRINGS "${source}" lines REGEX "\"[^\"]+\\.[A-Za-z0-9]+\"")
    foreach(line IN LISTS lines)
        string(REGEX MATCHALL "\"[^\"]+\\.[A-Za-z0-9]+\"" literals "${line}")
        foreach(literal IN LISTS literals)
            string(REGEX REPLACE "^\"(\\./)?(.*)\"$" "\\2" name "${literal}")
            list(APPEND named_files "${name}")
        endforeach()
    endforeach()
endforeach()
list(REMOVE_DUPLICATES named_files)

foreach(name IN LISTS named_files)
    if(EXISTS "${LAB_DIR}/${name}" OR name MATCHES "\\\\|\\.\\.")
        continue()
    endif()
    string(TOLOWER "${name}" lower_name)
    list(FIND lower_names "${lower_name}" index)
    if(index GREATER_EQUAL 0)
        list(GET lab_files ${index} lab_file)
        link_asset("${name}" "${lab_file}")
    endif()
endforeach()
