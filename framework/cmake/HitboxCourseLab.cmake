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
#     headers take its place, except its GameState and any edited file the user chooses
#     to build, and a file a student edited is named in one line
#     (HitboxCourseLabFramework.cmake);
#   - the .cpp files its Visual Studio project compiles (the .vcxproj's ClCompile list) are
#     compiled, not the stray copies beside them; every .cpp when there is no project. A
#     .cpp left out of the list whose header the code includes is named in one line;
#   - <windows.h> off Windows: a stand-in for the calls labs make, said in one line;
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

if(CMAKE_SCRIPT_MODE_FILE)
    cmake_minimum_required(VERSION 3.16) # the policies of a project, for the script modes below
endif()
set(HITBOX_COURSE_LAB_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/HitboxCourseLabFramework.cmake")

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

# Sets `out_var` to the files a Visual Studio project compiles: its <ClCompile Include="..."/>
# items in order, backslashes made slashes, as Visual Studio reads them: an item inside an
# XML comment is not one, and an item excluded from the build (<ExcludedFromBuild> true for
# every configuration, or for a Debug one, which is what students build) is left out.
# CMake has no XML reader and students build course labs with no Python, so the project's
# few elements are read here; tests/course/CMakeLists.txt checks it on tests/support/vcxproj/.
function(hitbox_read_project_sources out_var project)
    file(READ "${project}" text)
    string(REGEX REPLACE "<!--([^-]|-[^-])*-->" "" text "${text}") # XML allows no -- inside
    set(sources "")
    set(item_regex "<ClCompile[ \t\r\n]+Include=\"([^\"]+)\"[^>]*>")
    string(REGEX MATCH "${item_regex}" item "${text}")
    while(item)
        set(listed "${CMAKE_MATCH_1}")
        string(FIND "${text}" "${item}" start)
        string(LENGTH "${item}" item_length)
        math(EXPR after "${start} + ${item_length}")
        string(SUBSTRING "${text}" ${after} -1 text)
        set(body "")
        if(NOT item MATCHES "/>$") # <ClCompile ...> ... </ClCompile>: its settings
            string(FIND "${text}" "</ClCompile>" body_end)
            string(SUBSTRING "${text}" 0 ${body_end} body)
        endif()
        string(REPLACE "&amp;" "&" listed "${listed}")
        string(REPLACE "\\" "/" listed "${listed}")
        if(NOT body MATCHES "<ExcludedFromBuild( Condition=\"[^\"]*Debug[^\"]*\")?>[ \t]*true")
            list(APPEND sources "${listed}")
        endif()
        string(REGEX MATCH "${item_regex}" item "${text}")
    endwhile()
    set(${out_var} "${sources}" PARENT_SCOPE)
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

# One line for each .cpp in the folder that the project leaves out while the code includes
# its header (Ball.cpp beside an included Ball.h): the link will miss what it defines, as it
# would in Visual Studio. The project's list is kept; only the student can tell which is right.
function(hitbox_report_unlisted_sources lab_folder project_name lab_files compiled_files)
    set(included "")
    foreach(lab_file IN LISTS lab_files)
        file(STRINGS "${lab_folder}/${lab_file}" lines REGEX "#[ \t]*include[ \t]*\"")
        foreach(line IN LISTS lines)
            string(REGEX REPLACE "^.*include[ \t]*\"([^\"]*)\".*$" "\\1" named "${line}")
            string(REPLACE "\\" "/" named "${named}")
            get_filename_component(named "${named}" NAME)
            string(TOLOWER "${named}" named)
            list(APPEND included "${named}")
        endforeach()
    endforeach()
    foreach(lab_file IN LISTS lab_files)
        if(NOT lab_file MATCHES "\\.cpp$" OR lab_file IN_LIST compiled_files)
            continue()
        endif()
        get_filename_component(stem "${lab_file}" NAME_WE)
        string(TOLOWER "${stem}.h" header)
        if(header IN_LIST included)
            message(STATUS "Course lab: ${lab_file} is in the folder but not in ${project_name}, "
                           "whose code includes ${stem}.h; if the link fails, add ${lab_file} "
                           "to the project (Add > Existing Item)")
        endif()
    endforeach()
endfunction()

# Sets `out_files` to the lab's files to compile (relative paths): the Visual Studio project's
# ClCompile list when the folder has a project, else every .cpp; `out_from` says which.
function(hitbox_course_lab_compiled_files out_files out_from lab_folder lab_files)
    file(GLOB projects "${lab_folder}/*.vcxproj")
    set(compiled_files "")
    if(projects)
        list(GET projects 0 project)
        hitbox_read_project_sources(listed_sources "${project}")
        foreach(listed IN LISTS listed_sources)
            hitbox_find_ignoring_case(found "${listed}" "${lab_files}")
            if(found)
                list(APPEND compiled_files "${found}")
            elseif(NOT listed MATCHES "^Framework/")
                message(WARNING "${project} compiles ${listed}, which is not in the lab folder")
            endif()
        endforeach()
        get_filename_component(project_name "${project}" NAME)
        set(compiled_from "the ClCompile list of ${project_name}")
        hitbox_report_unlisted_sources("${lab_folder}" "${project_name}" "${lab_files}" "${compiled_files}")
    else()
        set(compiled_files ${lab_files})
        list(FILTER compiled_files INCLUDE REGEX "\\.cpp$")
        set(compiled_from "every .cpp (no .vcxproj)")
    endif()
    set(${out_files} "${compiled_files}" PARENT_SCOPE)
    set(${out_from} "${compiled_from}" PARENT_SCOPE)
    if(NOT compiled_files)
        message(FATAL_ERROR
            "HITBOX_COURSE_LAB_DIR: no .cpp files to compile in ${lab_folder} (outside "
            "Framework/ and SFML/). Give the lab folder that holds Main.cpp.")
    endif()
endfunction()

# The course's classes in Hitbox for one lab (library hitbox_course2025 or hitbox_course_compat,
# linked into course_lab), compiled against the lab's own GameState.h (and any edited header
# it chose to build) in the overlay folder; a class the lab brings its own .cpp for is not
# compiled from Hitbox's. Reads what hitbox_use_course_lab_framework set in the caller
# (COURSE_LAB_OVERLAY, COURSE_LAB_OWN_CLASSES).
function(hitbox_add_course_classes generation compat_folder)
    if(generation EQUAL 2025)
        file(GLOB compat_sources CONFIGURE_DEPENDS "${compat_folder}/Framework/*.cpp")
        set(library hitbox_course2025)
    else()
        set(compat_sources "")
        foreach(class_name AudioManager MusicObject SoundObject TileMap GameState)
            list(APPEND compat_sources "${compat_folder}/Framework/${class_name}.cpp")
        endforeach()
        set(library hitbox_course_compat)
    endif()
    foreach(class_name IN LISTS COURSE_LAB_OWN_CLASSES)
        list(REMOVE_ITEM compat_sources "${compat_folder}/Framework/${class_name}.cpp")
    endforeach()
    if(generation EQUAL 2025)
        # Built on Hitbox's object layer (GameObject, Animation; Hitbox's own classes are in
        # namespace hitbox, so the course's names are free). A lab's own Animation.cpp is
        # linked before the layer's, which is then never pulled in.
        add_library(${library} STATIC ${compat_sources})
        target_link_libraries(${library} PUBLIC hitbox_objects)
    else()
        add_library(${library} STATIC ${compat_sources})
        target_link_libraries(${library} PUBLIC hitbox_course_2019)
        # Before main(): with no sound device, OpenAL Soft's silent driver and one line
        # instead of an error for every sound (SFML 2 only: SFML 3 says it once itself).
        # An object library: its objects are always linked, so its initializer runs.
        add_library(hitbox_course_silent_audio OBJECT
            "${PROJECT_SOURCE_DIR}/framework/compat/SilentAudio.cpp")
        hitbox_warnings(hitbox_course_silent_audio)
        target_link_libraries(hitbox_course_silent_audio PRIVATE hitbox_platform)
        target_link_libraries(course_lab PRIVATE hitbox_course_silent_audio)
    endif()
    target_include_directories(${library} BEFORE PUBLIC "${COURSE_LAB_OVERLAY}" "${compat_folder}")
    hitbox_warnings(${library})
    if(NOT MSVC)
        # The lab's own headers in the overlay may carry MSVC's #pragma warning lines.
        target_compile_options(${library} PRIVATE -Wno-unknown-pragmas)
    endif()
    target_link_libraries(course_lab PRIVATE ${library})
    # The course's own files include their neighbours without the folder ("GameObject.h"
    # in Framework/TileMap.h): when the lab builds some of them, Hitbox's neighbours are
    # found that way too, last.
    if(HITBOX_COURSE_LAB_OWN_FRAMEWORK)
        target_include_directories(${library} PUBLIC "${compat_folder}/Framework")
    endif()
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
    # ...but the lab's own GameState and any edited Framework/ file it chose to build stay
    # (HitboxCourseLabFramework.cmake): headers in the overlay folder, sources compiled here.
    hitbox_use_course_lab_framework("${lab_folder}" ${generation} "${compat_folder}")
    list(REMOVE_ITEM lab_files ${COURSE_LAB_OWN_HEADERS})

    # What to compile: the Visual Studio project's ClCompile list when there is a project.
    hitbox_course_lab_compiled_files(compiled_files compiled_from "${lab_folder}" "${lab_files}")

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

    list(APPEND copied_sources ${COURSE_LAB_OWN_SOURCES})
    add_executable(course_lab ${copied_files} ${COURSE_LAB_OWN_SOURCES})
    # Win32 calls, off Windows: Hitbox's stand-in (framework/compat/windows/windows.h).
    if(NOT WIN32)
        foreach(original IN LISTS original_files)
            # file(STRINGS) follows a byte-order mark, so a UTF-16 Main.cpp is read too.
            file(STRINGS "${original}" windows_include REGEX "#[ \t]*include[ \t]*[<\"][Ww][Ii][Nn][Dd][Oo][Ww][Ss]\\.[Hh][>\"]")
            if(windows_include)
                file(RELATIVE_PATH shown "${lab_folder}" "${original}")
                message(STATUS "Course lab: ${shown} includes <windows.h>; on ${CMAKE_SYSTEM_NAME} "
                               "Hitbox's stand-in gives GetSystemMetrics(SM_CXSCREEN/SM_CYSCREEN) "
                               "from the desktop size and Sleep() (framework/compat/windows/)")
                target_include_directories(course_lab SYSTEM PRIVATE
                    "${PROJECT_SOURCE_DIR}/framework/compat/windows")
                break()
            endif()
        endforeach()
    endif()
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

    hitbox_add_course_classes(${generation} "${compat_folder}")
    # The lab's converted copies first (its own includes: "Level.h"), then the overlay (its
    # GameState.h), then Hitbox's "Framework/X.h" headers. The original folder is
    # deliberately not on the path.
    target_include_directories(course_lab BEFORE PRIVATE "${copy_folder}" "${COURSE_LAB_OVERLAY}" "${compat_folder}")

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

# Script mode, for check-course-labs (scripts/labtool/courselabs.py): prints a folder's generation (2019 or 2025).
#   cmake -DHITBOX_PRINT_GENERATION_OF=<folder> -P HitboxCourseLab.cmake
if(CMAKE_SCRIPT_MODE_FILE AND HITBOX_PRINT_GENERATION_OF)
    hitbox_find_course_lab_generation("${HITBOX_PRINT_GENERATION_OF}")
    execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "${HITBOX_COURSE_LAB_GENERATION}")
endif()
# Script mode, for the tests: the files a .vcxproj compiles, one a line.
#   cmake -DHITBOX_PRINT_PROJECT_SOURCES_OF=<project.vcxproj> -P HitboxCourseLab.cmake
if(CMAKE_SCRIPT_MODE_FILE AND HITBOX_PRINT_PROJECT_SOURCES_OF)
    hitbox_read_project_sources(listed "${HITBOX_PRINT_PROJECT_SOURCES_OF}")
    string(REPLACE ";" "\n" lines "${listed}")
    execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "${lines}")
endif()
# Script mode, for tests/course/write_framework_hashes.py: the Framework/ files whose lab
# copy is always used, one a line.
#   cmake -DHITBOX_PRINT_ALWAYS_OWN=ON -P HitboxCourseLab.cmake
if(CMAKE_SCRIPT_MODE_FILE AND HITBOX_PRINT_ALWAYS_OWN)
    string(REPLACE ";" "\n" lines "${HITBOX_COURSE_LAB_ALWAYS_OWN}")
    execute_process(COMMAND "${CMAKE_COMMAND}" -E echo "${lines}")
endif()
# Script mode, for the tests: the lines configure prints about a folder's edited Framework/.
#   cmake -DHITBOX_REPORT_EDITED_FRAMEWORK_OF=<folder> -P HitboxCourseLab.cmake
if(CMAKE_SCRIPT_MODE_FILE AND HITBOX_REPORT_EDITED_FRAMEWORK_OF)
    get_filename_component(lab_folder "${HITBOX_REPORT_EDITED_FRAMEWORK_OF}" ABSOLUTE)
    hitbox_find_course_lab_generation("${lab_folder}")
    hitbox_report_edited_framework_files("${lab_folder}" ${HITBOX_COURSE_LAB_GENERATION})
endif()
