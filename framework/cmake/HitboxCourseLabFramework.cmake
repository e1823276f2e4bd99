# The course's own Framework/ files in a lab folder: which of them the lab's build uses.
# Included by HitboxCourseLab.cmake.
#
# Hitbox builds its own versions of the course's classes in their place, except:
#   - GameState.h (and GameState.cpp): the course invites students to edit its enum of
#     states, so the lab's copy is always used (in Framework/ or beside Main.cpp);
#   - files named in HITBOX_COURSE_LAB_OWN_FRAMEWORK: a student's edited copy, built
#     against Hitbox instead of Hitbox's version.
# A Framework/ file that differs from every copy the course shipped (a table of their
# SHA-256 hashes per generation, framework/compat/course-framework-hashes.json, written by
# tests/course/write_framework_hashes.py) is named in one line at configure time, so a
# student's edit is never replaced without a word.
#
# The lab's own headers are converted into an overlay folder at configure time (the
# course's classes in Hitbox are compiled against them, so they must exist before any
# build step); the overlay goes first on the include path. Its .cpp files are converted
# there too (beside their headers, which they include as "GameState.h") and compiled as lab
# code.

if(NOT CMAKE_SCRIPT_MODE_FILE)
    set(HITBOX_COURSE_LAB_OWN_FRAMEWORK "" CACHE STRING
        "Course lab Framework/ files to build from the lab's own (edited) copy, e.g. Framework/Input.cpp")
endif()
set(HITBOX_COURSE_FRAMEWORK_HASHES "${CMAKE_CURRENT_LIST_DIR}/../compat/course-framework-hashes.json")

# The course classes that 2019-24 labs may replace: the ones Hitbox implements in
# framework/compat/ per lab. GameObject, Input, BaseLevel and Vector are built once
# (hitbox_course_2019, on Hitbox's own classes) and Collision and Animation are Hitbox's own,
# so a lab cannot swap them.
set(HITBOX_COURSE_2019_REPLACEABLE AudioManager SoundObject MusicObject TileMap GameState)
# The Framework/ files whose lab copy is always used (see above): never compared with the
# course's, and left out of the table (tests/course/write_framework_hashes.py asks here).
set(HITBOX_COURSE_LAB_ALWAYS_OWN Framework/GameState.h Framework/GameState.cpp)

# Converts one lab file into the overlay now (configure time), and re-runs CMake when it
# changes.
function(hitbox_convert_into_overlay lab_folder relative overlay_folder search_dirs)
    execute_process(
        COMMAND "${CMAKE_COMMAND}" "-DINPUT=${lab_folder}/${relative}"
                "-DOUTPUT=${overlay_folder}/${relative}" "-DLAB_DIR=${lab_folder}"
                "-DSEARCH_DIRS=${search_dirs}"
                -P "${HITBOX_COURSE_LAB_MODULE_DIR}/HitboxConvertCourseSource.cmake"
        RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "Course lab: could not convert ${lab_folder}/${relative}")
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${lab_folder}/${relative}")
endfunction()

# Says, one line per file, which of the lab's Framework/ files differ from the course's.
function(hitbox_report_edited_framework_files lab_folder generation)
    if(CMAKE_VERSION VERSION_LESS 3.19)
        message(STATUS "Course lab: CMake ${CMAKE_VERSION} cannot read the table of the course's "
                       "Framework/ files (3.19 can): a student's edits to them are not looked for")
        return()
    endif()
    file(READ "${HITBOX_COURSE_FRAMEWORK_HASHES}" table)
    if(NOT CMAKE_SCRIPT_MODE_FILE)
        set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${HITBOX_COURSE_FRAMEWORK_HASHES}")
    endif()
    file(GLOB framework_files RELATIVE "${lab_folder}" "${lab_folder}/Framework/*")
    foreach(relative IN LISTS framework_files)
        if(relative IN_LIST HITBOX_COURSE_LAB_ALWAYS_OWN OR relative IN_LIST HITBOX_COURSE_LAB_OWN_FRAMEWORK)
            continue()
        endif()
        # Only files the table knows: a file the course never shipped is the student's own.
        string(JSON shipped ERROR_VARIABLE unknown GET "${table}" "generations" "${generation}" "${relative}")
        if(unknown)
            continue()
        endif()
        file(SHA256 "${lab_folder}/${relative}" hash)
        string(FIND "${shipped}" "\"${hash}\"" position)
        if(position EQUAL -1)
            get_filename_component(class_name "${relative}" NAME_WE)
            message(STATUS "Course lab: your ${relative} differs from the course's; Hitbox's "
                           "${class_name} is built in its place (to build yours: "
                           "-DHITBOX_COURSE_LAB_OWN_FRAMEWORK=${relative})")
        endif()
    endforeach()
endfunction()

# Sets, in the caller:
#   COURSE_LAB_OVERLAY        the folder to put first on the include path
#   COURSE_LAB_OWN_SOURCES    the lab's Framework/ .cpp files, converted, to compile as lab code
#   COURSE_LAB_OWN_HEADERS    the lab's headers in the overlay (relative paths)
#   COURSE_LAB_OWN_CLASSES    class names whose compat .cpp must not be compiled
function(hitbox_use_course_lab_framework lab_folder generation compat_folder)
    set(overlay "${CMAKE_CURRENT_BINARY_DIR}/course_lab_framework")
    file(REMOVE_RECURSE "${overlay}")
    file(MAKE_DIRECTORY "${overlay}/Framework")
    hitbox_report_edited_framework_files("${lab_folder}" ${generation})
    set(own_classes "")

    # The lab's own GameState, wherever it keeps it.
    set(own_files "")
    foreach(candidate ${HITBOX_COURSE_LAB_ALWAYS_OWN} GameState.h)
        if(EXISTS "${lab_folder}/${candidate}")
            list(APPEND own_files "${candidate}")
        endif()
    endforeach()
    # ...and the edited files the user chose, each with its header or source.
    foreach(chosen IN LISTS HITBOX_COURSE_LAB_OWN_FRAMEWORK)
        if(NOT chosen MATCHES "^Framework/([A-Za-z0-9_]+)\\.(h|cpp)$")
            message(FATAL_ERROR "HITBOX_COURSE_LAB_OWN_FRAMEWORK: '${chosen}' is not a "
                                "Framework/ file (give it as Framework/Input.cpp)")
        endif()
        set(class_name "${CMAKE_MATCH_1}")
        if(NOT EXISTS "${lab_folder}/${chosen}")
            message(FATAL_ERROR "HITBOX_COURSE_LAB_OWN_FRAMEWORK: ${lab_folder}/${chosen} does not exist")
        endif()
        if(generation EQUAL 2019 AND NOT class_name IN_LIST HITBOX_COURSE_2019_REPLACEABLE)
            message(FATAL_ERROR "HITBOX_COURSE_LAB_OWN_FRAMEWORK: in 2019-24 labs ${class_name} "
                                "is Hitbox's own class and cannot be swapped; only "
                                "${HITBOX_COURSE_2019_REPLACEABLE} can")
        endif()
        foreach(extension h cpp)
            if(EXISTS "${lab_folder}/Framework/${class_name}.${extension}")
                list(APPEND own_files "Framework/${class_name}.${extension}")
            endif()
        endforeach()
        list(APPEND own_classes ${class_name})
        message(STATUS "Course lab: building your own Framework/${class_name} against Hitbox")
    endforeach()
    list(REMOVE_DUPLICATES own_files)

    set(own_sources "")
    set(own_headers "")
    foreach(relative IN LISTS own_files)
        get_filename_component(class_name "${relative}" NAME_WE)
        hitbox_convert_into_overlay("${lab_folder}" "${relative}" "${overlay}" "${compat_folder}")
        if(relative MATCHES "\\.cpp$")
            list(APPEND own_sources "${overlay}/${relative}")
            list(APPEND own_classes ${class_name})
        else()
            list(APPEND own_headers "${relative}")
        endif()
    endforeach()
    # A GameState.h beside Main.cpp: the course's headers include it as Framework/GameState.h.
    if("GameState.h" IN_LIST own_files AND NOT "Framework/GameState.h" IN_LIST own_files)
        file(WRITE "${overlay}/Framework/GameState.h"
            "// Written by HitboxCourseLab: the lab keeps its GameState.h beside Main.cpp.\n"
            "#pragma once\n#include \"../GameState.h\"\n")
    endif()
    if(EXISTS "${lab_folder}/GameState.cpp")
        list(APPEND own_classes GameState)
    endif()
    list(REMOVE_DUPLICATES own_classes)
    set(COURSE_LAB_OVERLAY "${overlay}" PARENT_SCOPE)
    set(COURSE_LAB_OWN_SOURCES "${own_sources}" PARENT_SCOPE)
    set(COURSE_LAB_OWN_HEADERS "${own_headers}" PARENT_SCOPE)
    set(COURSE_LAB_OWN_CLASSES "${own_classes}" PARENT_SCOPE)
endfunction()
