# Builds a lab folder written for the course's own framework (Main.cpp, Level.h/.cpp, the
# lab's object classes) as the program `course_lab`, on Hitbox. The root CMakeLists.txt
# calls it when HITBOX_COURSE_LAB_DIR is set:
#
#   cmake -S . -B build-lab -DHITBOX_COURSE_LAB_DIR=<folder>
#   cmake --build build-lab --target run_course_lab      (builds, then runs it)
#
# Two generations of the course's framework exist, and the folder says which it is:
#   2019-24  pointers (Level(&window, &input)), int key codes, SFML 2:
#            framework/compat/Framework/ over Hitbox's GameObject, Collision, Input...
#   2025-26  references (Level(window, input)), Scancodes, SFML 3:
#            framework/compat/course2025/Framework/, the course's classes on Hitbox's maths.
# hitbox_find_course_lab_generation() tells them apart before SFML is looked for, since
# the generation decides which SFML major the lab needs.
#
# What it does about the folder as Visual Studio saved it:
#   - its own Framework/ copy (and the Windows-only SFML/ copy) is ignored: Hitbox's
#     headers take its place. One exception: the course invites students to edit
#     Framework/GameState.h (its enum of states), so the lab's copy of that header (and of
#     GameState.cpp) is used when there is one;
#   - the .cpp files its Visual Studio project compiles (the .vcxproj's ClCompile list) are
#     compiled, not the stray copies beside them; every .cpp when there is no project;
#   - every source and header is copied into the build tree by
#     HitboxConvertCourseSource.cmake (UTF-16 and byte-order marks, backslash includes,
#     includes whose letter case differs from the file's), at build time;
#   - lab files (only those) are compiled the way Visual Studio accepts them: with the
#     standard headers its own headers pull in (framework/compat/CourseLabIncludes.h), with
#     g++'s -fpermissive (a member named like its type, `Ball Ball;`), and without Hitbox's
#     warnings-as-errors;
#   - the program runs from a folder in the build tree that links to the lab folder's
#     assets, with extra names for files the code spells with other letter case
#     (HitboxCourseLabAssets.cmake), so gfx/, font/ and sfx/ paths load as on Windows.

set(HITBOX_COURSE_LAB_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}")

# Sets HITBOX_COURSE_LAB_GENERATION (2019 or 2025) and HITBOX_COURSE_LAB_SFML_MAJOR (2 or 3)
# from the folder's own Framework/ headers or, without them, from its code.
function(hitbox_find_course_lab_generation lab_folder)
    get_filename_component(lab_folder "${lab_folder}" ABSOLUTE BASE_DIR "${CMAKE_SOURCE_DIR}")
    # What only the 2025-26 framework writes (m_ members, Scancodes, BaseLevel taking the
    # window by reference) and what only its labs write (SFML 3's event->getIf<>(),
    # Scancodes). A reference to a window alone is no sign in lab code: older labs have
    # helpers taking one.
    set(signs "m_velocity|m_collisionBox|Scancode|Scan::|RenderWindow&")
    set(evidence "")
    foreach(header GameObject.h Input.h BaseLevel.h)
        if(EXISTS "${lab_folder}/Framework/${header}")
            list(APPEND evidence "${lab_folder}/Framework/${header}")
        endif()
    endforeach()
    if(NOT evidence)
        set(signs "getIf<|Scancode|Scan::|m_velocity|m_collisionBox")
        file(GLOB evidence "${lab_folder}/*.cpp" "${lab_folder}/*.h")
    endif()
    set(generation 2019)
    foreach(file IN LISTS evidence)
        # file(STRINGS) follows a byte-order mark, so a UTF-16 Main.cpp is read too.
        file(STRINGS "${file}" found REGEX "${signs}")
        if(found)
            set(generation 2025)
            break()
        endif()
    endforeach()
    set(HITBOX_COURSE_LAB_GENERATION ${generation} PARENT_SCOPE)
    if(generation EQUAL 2025)
        set(HITBOX_COURSE_LAB_SFML_MAJOR 3 PARENT_SCOPE)
    else()
        set(HITBOX_COURSE_LAB_SFML_MAJOR 2 PARENT_SCOPE)
    endif()
endfunction()

# Finds, ignoring letter case, the file of `files` (relative paths) that `wanted` names.
function(hitbox_find_ignoring_case out_var wanted files)
    string(TOLOWER "${wanted}" wanted)
    set(${out_var} "" PARENT_SCOPE)
    foreach(file IN LISTS files)
        string(TOLOWER "${file}" lower_file)
        if(lower_file STREQUAL wanted)
            set(${out_var} "${file}" PARENT_SCOPE)
            return()
        endif()
    endforeach()
endfunction()

function(hitbox_add_course_lab lab_folder)
    get_filename_component(lab_folder "${lab_folder}" ABSOLUTE BASE_DIR "${CMAKE_SOURCE_DIR}")
    if(NOT IS_DIRECTORY "${lab_folder}")
        message(FATAL_ERROR
            "HITBOX_COURSE_LAB_DIR: ${lab_folder} is not a folder. "
            "Give the lab folder that holds Main.cpp, e.g. -DHITBOX_COURSE_LAB_DIR=C:/labs/Week8")
    endif()
    hitbox_find_course_lab_generation("${lab_folder}")
    set(generation ${HITBOX_COURSE_LAB_GENERATION})
    set(needed_major ${HITBOX_COURSE_LAB_SFML_MAJOR})
    if(generation EQUAL 2025)
        set(described "the 2025-26 course framework (references, Scancodes, SFML 3)")
        set(compat_folder "${PROJECT_SOURCE_DIR}/framework/compat/course2025")
    else()
        set(described "the 2019-24 course framework (pointers, SFML 2)")
        set(compat_folder "${PROJECT_SOURCE_DIR}/framework/compat")
    endif()
    if(DEFINED SFML_VERSION_MAJOR AND NOT SFML_VERSION_MAJOR EQUAL needed_major)
        message(FATAL_ERROR
            "Course lab ${lab_folder} is written for ${described} and needs SFML "
            "${needed_major}, but this build found SFML ${SFML_VERSION}. Build it where SFML "
            "${needed_major} is installed (on Debian 12, SFML 3 is in scripts/sid-root.sh).")
    endif()

    # The folder's sources, without the parts that Hitbox replaces (Framework/, SFML/) and
    # without anything a build or Visual Studio left there.
    file(GLOB_RECURSE lab_files CONFIGURE_DEPENDS RELATIVE "${lab_folder}"
        "${lab_folder}/*.cpp" "${lab_folder}/*.h" "${lab_folder}/*.hpp")
    list(FILTER lab_files EXCLUDE REGEX "^(SFML|x64|x86|Debug|Release|\\.vs)/")
    list(FILTER lab_files EXCLUDE REGEX "^Framework/(.*/)?[^/]*$")
    list(FILTER lab_files EXCLUDE REGEX "(^|/)(CMakeFiles|course_lab_[a-z]+|_deps)/")
    # ...but the lab's own edited GameState (see above) stays.
    foreach(own_file Framework/GameState.h Framework/GameState.cpp)
        if(EXISTS "${lab_folder}/${own_file}")
            list(APPEND lab_files "${own_file}")
        endif()
    endforeach()

    # What to compile: the Visual Studio project's ClCompile list when there is a project.
    file(GLOB projects "${lab_folder}/*.vcxproj")
    set(compiled_files "")
    if(projects)
        list(GET projects 0 project)
        file(READ "${project}" project_text)
        string(REGEX MATCHALL "<ClCompile[ \t\r\n]+Include=\"[^\"]+\"" entries "${project_text}")
        foreach(entry IN LISTS entries)
            string(REGEX REPLACE "^.*Include=\"([^\"]+)\"$" "\\1" listed "${entry}")
            string(REPLACE "\\" "/" listed "${listed}")
            hitbox_find_ignoring_case(found "${listed}" "${lab_files}")
            if(found)
                list(APPEND compiled_files "${found}")
            elseif(NOT listed MATCHES "^Framework/")
                message(WARNING "${project} compiles ${listed}, which is not in the lab folder")
            endif()
        endforeach()
        get_filename_component(project_name "${project}" NAME)
        set(compiled_from "the ClCompile list of ${project_name}")
    else()
        set(compiled_files ${lab_files})
        list(FILTER compiled_files INCLUDE REGEX "\\.cpp$")
        set(compiled_from "every .cpp (no .vcxproj)")
    endif()
    if(NOT compiled_files)
        message(FATAL_ERROR
            "HITBOX_COURSE_LAB_DIR: no .cpp files to compile in ${lab_folder} (outside "
            "Framework/ and SFML/). Give the lab folder that holds Main.cpp.")
    endif()

    # Copy (and convert) each file into the build tree, keeping the folder's layout so that
    # the lab's own includes ("Level.h", "Objects/Ball.h") still find each other.
    set(copy_folder "${CMAKE_CURRENT_BINARY_DIR}/course_lab_sources")
    set(converter "${HITBOX_COURSE_LAB_MODULE_DIR}/HitboxConvertCourseSource.cmake")
    set(copied_files "")
    set(copied_sources "")
    set(original_files "")
    foreach(lab_file IN LISTS lab_files)
        if(lab_file MATCHES "\\.cpp$" AND NOT lab_file IN_LIST compiled_files)
            continue() # a stray .cpp the project does not build
        endif()
        set(copy "${copy_folder}/${lab_file}")
        add_custom_command(OUTPUT "${copy}"
            COMMAND "${CMAKE_COMMAND}" "-DINPUT=${lab_folder}/${lab_file}" "-DOUTPUT=${copy}"
                    "-DLAB_DIR=${lab_folder}" "-DSEARCH_DIRS=${compat_folder}"
                    -P "${converter}"
            DEPENDS "${lab_folder}/${lab_file}" "${converter}"
            COMMENT "Converting course lab file ${lab_file}"
            VERBATIM)
        list(APPEND copied_files "${copy}")
        list(APPEND original_files "${lab_folder}/${lab_file}")
        if(lab_file MATCHES "\\.cpp$")
            list(APPEND copied_sources "${copy}")
        endif()
    endforeach()

    add_executable(course_lab ${copied_files})
    # The lab's own files: Visual Studio's implicit standard headers, and -fpermissive for
    # what it accepts and g++ does not. Hitbox's code is never compiled this way.
    set(implicit_includes "${PROJECT_SOURCE_DIR}/framework/compat/CourseLabIncludes.h")
    if(MSVC)
        set(lab_options "/FI${implicit_includes}")
    else()
        set(lab_options "-include${implicit_includes}" -fpermissive -Wno-unknown-pragmas)
    endif()
    set_source_files_properties(${copied_sources} PROPERTIES COMPILE_OPTIONS "${lab_options}")
    # No hitbox_warnings(): lab code is built with the compiler's default warnings and
    # never with -Werror, whatever HITBOX_WARNINGS_AS_ERRORS says. Still /utf-8 and the DLLs.
    hitbox_portable_settings(course_lab)

    if(generation EQUAL 2025)
        file(GLOB compat_sources CONFIGURE_DEPENDS "${compat_folder}/Framework/*.cpp")
        # Hitbox's Animation is the course's Animation; nothing else of the object layer is:
        # the 2019-24 classes of the same names (GameObject, Input, BaseLevel) must not be
        # linked into the same program, so the course's classes sit on Hitbox's maths only.
        add_library(hitbox_course2025 STATIC ${compat_sources}
            "${PROJECT_SOURCE_DIR}/framework/hitbox/objects/Animation.cpp")
        target_include_directories(hitbox_course2025 PUBLIC "${compat_folder}")
        target_link_libraries(hitbox_course2025 PUBLIC hitbox_sfml hitbox_geometry)
        hitbox_warnings(hitbox_course2025)
        target_link_libraries(course_lab PRIVATE hitbox_course2025)
    else()
        add_library(hitbox_course_compat STATIC
            "${compat_folder}/Framework/AudioManager.cpp"
            "${compat_folder}/Framework/MusicObject.cpp"
            "${compat_folder}/Framework/SoundObject.cpp"
            "${compat_folder}/Framework/TileMap.cpp")
        target_include_directories(hitbox_course_compat PUBLIC "${compat_folder}")
        target_link_libraries(hitbox_course_compat PUBLIC hitbox sfml-audio)
        hitbox_warnings(hitbox_course_compat)
        target_link_libraries(course_lab PRIVATE hitbox_course_compat)
        # GameState is compiled with the lab's header, which may have more states.
        if(NOT "Framework/GameState.cpp" IN_LIST compiled_files)
            target_sources(course_lab PRIVATE "${compat_folder}/Framework/GameState.cpp")
        endif()
    endif()
    # The lab's copy first: only its Framework/GameState.h can be there (see above), and it
    # must win over Hitbox's. Then Hitbox's "Framework/X.h" headers. The original folder is
    # deliberately not on the path.
    target_include_directories(course_lab BEFORE PRIVATE "${copy_folder}" "${compat_folder}")

    # The folder the program runs from: the lab's assets, letter case forgiven.
    set(run_folder "${CMAKE_CURRENT_BINARY_DIR}/course_lab_run")
    add_custom_target(course_lab_assets
        COMMAND "${CMAKE_COMMAND}" "-DLAB_DIR=${lab_folder}" "-DRUN_DIR=${run_folder}"
                "-DSOURCES=${original_files}"
                -P "${HITBOX_COURSE_LAB_MODULE_DIR}/HitboxCourseLabAssets.cmake"
        COMMENT "Linking the course lab's assets into ${run_folder}"
        VERBATIM)
    add_dependencies(course_lab course_lab_assets)
    set_target_properties(course_lab PROPERTIES VS_DEBUGGER_WORKING_DIRECTORY "${run_folder}")
    add_custom_target(run_course_lab
        COMMAND course_lab
        DEPENDS course_lab
        WORKING_DIRECTORY "${run_folder}"
        COMMENT "Running the course lab in ${run_folder}"
        VERBATIM
        USES_TERMINAL)
    list(LENGTH copied_sources compiled_count)
    message(STATUS "Course lab: ${lab_folder}: ${described}; ${compiled_count} files from "
                   "${compiled_from} -> target course_lab, runs in ${run_folder}")
endfunction()

# Script mode, for scripts/check-course-labs.sh: prints a folder's generation (2019 or 2025).
#   cmake -DHITBOX_PRINT_GENERATION_OF=<folder> -P HitboxCourseLab.cmake
if(CMAKE_SCRIPT_MODE_FILE AND HITBOX_PRINT_GENERATION_OF)
    hitbox_find_course_lab_generation("${HITBOX_PRINT_GENERATION_OF}")
    execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "${HITBOX_COURSE_LAB_GENERATION}")
endif()
