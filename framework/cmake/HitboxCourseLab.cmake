# hitbox_add_course_lab(<folder>): builds a lab folder written for the course's old
# framework (Main.cpp, Level.h/.cpp, the lab's object classes) as the program `course_lab`,
# linked with Hitbox. The root CMakeLists.txt calls it when HITBOX_COURSE_LAB_DIR is set:
#
#   cmake -S . -B build-lab -DHITBOX_COURSE_LAB_DIR=<folder>
#   cmake --build build-lab --target run_course_lab      (builds, then runs it from <folder>)
#
# What it does about the folder as Visual Studio saved it:
#   - its own Framework/ copy (and the Windows-only SFML/ copy) is ignored: Hitbox's
#     headers in framework/compat/Framework/ take its place;
#   - every source and header is copied into the build tree by
#     HitboxConvertCourseSource.cmake, which turns UTF-16 into UTF-8 and backslash includes
#     into forward-slash ones (at build time, so edits in the folder are picked up);
#   - <cmath> is included in every file, because the Windows headers include it for you
#     and lab code calls pow() without including it;
#   - the lab's own code is built without Hitbox's warnings-as-errors;
#   - the program runs from the lab folder, so its gfx/, font/ and sfx/ paths load.

set(HITBOX_COURSE_LAB_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}")

function(hitbox_add_course_lab lab_folder)
    get_filename_component(lab_folder "${lab_folder}" ABSOLUTE BASE_DIR "${CMAKE_SOURCE_DIR}")
    if(NOT IS_DIRECTORY "${lab_folder}")
        message(FATAL_ERROR
            "HITBOX_COURSE_LAB_DIR: ${lab_folder} is not a folder. "
            "Give the lab folder that holds Main.cpp, e.g. -DHITBOX_COURSE_LAB_DIR=C:/labs/Week8")
    endif()

    # The folder's sources, without the parts that Hitbox replaces (Framework/, SFML/) and
    # without anything a build or Visual Studio left there.
    file(GLOB_RECURSE lab_files CONFIGURE_DEPENDS RELATIVE "${lab_folder}"
        "${lab_folder}/*.cpp" "${lab_folder}/*.h" "${lab_folder}/*.hpp")
    list(FILTER lab_files EXCLUDE REGEX "^(Framework|SFML|x64|x86|Debug|Release|\\.vs)/")
    list(FILTER lab_files EXCLUDE REGEX "(^|/)(CMakeFiles|course_lab_sources|_deps)/")
    if(NOT lab_files MATCHES "\\.cpp")
        message(FATAL_ERROR
            "HITBOX_COURSE_LAB_DIR: no .cpp files in ${lab_folder} (outside Framework/ and SFML/). "
            "Give the lab folder that holds Main.cpp.")
    endif()

    # Copy (and convert) each file into the build tree, keeping the folder's layout so that
    # the lab's own includes ("Level.h", "Objects/Ball.h") still find each other.
    set(copy_folder "${CMAKE_CURRENT_BINARY_DIR}/course_lab_sources")
    set(converter "${HITBOX_COURSE_LAB_MODULE_DIR}/HitboxConvertCourseSource.cmake")
    set(copied_files "")
    foreach(lab_file IN LISTS lab_files)
        set(copy "${copy_folder}/${lab_file}")
        add_custom_command(OUTPUT "${copy}"
            COMMAND "${CMAKE_COMMAND}" "-DINPUT=${lab_folder}/${lab_file}" "-DOUTPUT=${copy}"
                    -P "${converter}"
            DEPENDS "${lab_folder}/${lab_file}" "${converter}"
            COMMENT "Converting course lab file ${lab_file}"
            VERBATIM)
        list(APPEND copied_files "${copy}")
    endforeach()

    add_executable(course_lab ${copied_files})
    target_link_libraries(course_lab PRIVATE hitbox)
    # BEFORE: "Framework/GameObject.h" must find Hitbox's compat header first, whatever
    # else is on the include path. The original folder is deliberately not on it.
    target_include_directories(course_lab BEFORE PRIVATE
        "${PROJECT_SOURCE_DIR}/framework/compat" "${copy_folder}")
    if(MSVC)
        target_compile_options(course_lab PRIVATE /FIcmath)
    else()
        target_compile_options(course_lab PRIVATE -include cmath)
    endif()
    # No hitbox_warnings(): lab code is built with the compiler's default warnings and
    # never with -Werror, whatever HITBOX_WARNINGS_AS_ERRORS says.

    # Run from the lab folder so "gfx/ball.png", "font/arial.ttf" and "sfx/hit.ogg" load.
    set_target_properties(course_lab PROPERTIES VS_DEBUGGER_WORKING_DIRECTORY "${lab_folder}")
    add_custom_target(run_course_lab
        COMMAND course_lab
        DEPENDS course_lab
        WORKING_DIRECTORY "${lab_folder}"
        COMMENT "Running the course lab from ${lab_folder}"
        VERBATIM
        USES_TERMINAL)
    message(STATUS "Course lab: ${lab_folder} -> target course_lab (run it from that folder, "
                   "or: cmake --build <build> --target run_course_lab)")
endfunction()
