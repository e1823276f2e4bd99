# The lab machinery: one solution source, two programs.
#
# In a lab folder (labs/NN_name/CMakeLists.txt):
#
#   hitbox_add_lab(lab02_bouncing_balls
#       MAIN main.cpp
#       SOURCES BallsLevel.cpp BallsLevel.h Ball.cpp Ball.h)
#
# builds, from the solution sources in the folder:
#   lab02_bouncing_balls_level            library: every SOURCES file (no main)
#   lab02_bouncing_balls                  the solution program
# and from the exercise sources that HitboxMakeExercise.cmake generates in the build tree
# (task blocks replaced by "// TASK n: ... — see README.md" and the starter code):
#   lab02_bouncing_balls_exercise_level
#   lab02_bouncing_balls_exercise         what a student starts from
#
# In the lab's grading-test folder (tests/labs/NN_name/CMakeLists.txt):
#
#   hitbox_add_lab_tests(lab02_bouncing_balls SOURCES BallsGradingTests.cpp)
#
# (plus, when they exist, the instructor's hidden variants tests/labs-hidden/NN_name/*.cpp:
# the same behaviour with other numbers, left out of the handout, run by the class grader)
# builds lab02_bouncing_balls_tests (against the solution; registered with ctest, label
# `lab`, names prefixed "lab02_bouncing_balls.") and lab02_bouncing_balls_exercise_tests
# (against the exercise; built but not registered: scripts/check-exercises.sh runs it to
# prove every task has a test that fails until the student does the task).
#
# Writing a lab: the exercise is compiled with the same warnings as the solution (errors in
# CI, with HITBOX_LAB_WARNINGS_AS_ERRORS), so starter code must compile cleanly: e.g. "// (void)dt;" in a STARTER
# block for a parameter only the solution uses. Grading tests can include
# "labs/LabTesting.h" (EXPECT_VEC_NEAR). scripts/check-exercises.sh checks that each task
# has a test (suite Task<n>...) that fails on the exercise.
#
# In a student handout (scripts/make-handout.sh copies scripts/labtool/handout/HitboxHandout.cmake
# into framework/cmake/; it sets HITBOX_HANDOUT) the lab folders already hold the exercise, so there is only one
# version: <lab>_level, <lab> and <lab>_tests build and test the student's own code.
#
# THE LAB FORMAT (what a new lab needs for the build, the handout and the class grader):
# - labs/NN_name/: CMakeLists.txt calling hitbox_add_lab, README.md (the lab sheet: tasks,
#   keys, which test suites check each task) and the sources. What students write sits
#   between "// BEGIN TASK n: title" and "// END TASK n". The files holding a marker are the
#   student's files: the class grader (scripts/lab.py grade-class) takes ONLY those from a
#   submission; every other file of the lab is the instructor's. So put code the tests
#   rely on, and that students must not change, in files without a marker.
# - tests/labs/NN_name/: CMakeLists.txt calling hitbox_add_lab_tests. Suites are named
#   Task<n><What> (Task2BounceOffWalls); a task earns its mark when all its tests pass.
#   Each task's tests exercise that task's code alone: set the state up directly or call
#   the task's function, never through another task's code, so one mistake costs one task
#   (scripts/check-fair-marks.sh leaves each task undone in turn and fails on a cascade).
#   Where a rule has an edge (walls, radii, tile bounds), test the touching case. Bound
#   every loop by a step count: a test takes well under a second on the solution and on the
#   starter (the grader stops a test after 5 s, as a last resort: scripts/labtool/limits.py).
#   scripts/check-mutants.py measures how many single-point wrong answers inside each task
#   block the tests catch (target 90 %, each costing its own task only; equivalent ones are
#   listed with a reason in tests/labs/equivalent-mutants.txt), and
#   scripts/check-sheet-numbers.py rebuilds a lab with the numbers its sheet invites students
#   to change: tests set the numbers they need.
# - tests/labs-hidden/NN_name/*.cpp (optional): the instructor's hidden variants, the same
#   behaviour with other numbers; built into <lab>_tests, left out of the handout.
include_guard(GLOBAL)
include(GoogleTest)
include(HitboxHandout OPTIONAL)

# Global properties, not variables: the include guard means only the first folder that
# includes this file (labs/) would see variables set here, and tests/labs/ needs them too.
set_property(GLOBAL PROPERTY HITBOX_LAB_HANDOUT "${HITBOX_HANDOUT}")
set_property(GLOBAL PROPERTY HITBOX_LAB_GENERATOR "${CMAKE_CURRENT_LIST_DIR}/HitboxMakeExercise.cmake")

# Compiler settings every lab target shares. Lab code is never built with warnings as
# errors, on any compiler and in any preset: a student's half-finished code (an unused
# variable) should warn, not stop the build. CI checks the instructor's solution and starter
# code strictly with -DHITBOX_LAB_WARNINGS_AS_ERRORS=ON (never in a handout).
option(HITBOX_LAB_WARNINGS_AS_ERRORS
       "CI only: treat warnings in the labs' solutions and starter code as errors" OFF)
function(_hitbox_lab_target_settings target)
    get_property(handout GLOBAL PROPERTY HITBOX_LAB_HANDOUT)
    if(HITBOX_LAB_WARNINGS_AS_ERRORS AND NOT handout)
        hitbox_warnings(${target} AS_ERRORS ON)
    else()
        hitbox_warnings(${target} AS_ERRORS OFF)
    endif()
    # Debug builds check every index into a standard container, so a loop that reads one past
    # the end of a vector stops with a message instead of passing by luck (undefined
    # behaviour). MSVC's Debug runtime checks already (_ITERATOR_DEBUG_LEVEL 2); this is
    # libstdc++'s switch (it keeps the ABI, unlike _GLIBCXX_DEBUG). On the lab, its exercise
    # and their tests alike, so the checked copy of each container function is the one linked.
    # The one warning that is always an error: a function that can end without returning its
    # value (undefined behaviour that may pass a test by luck). MSVC refuses it already (C4716).
    if(NOT MSVC)
        target_compile_definitions(${target} PRIVATE $<$<CONFIG:Debug>:_GLIBCXX_ASSERTIONS>)
        target_compile_options(${target} PRIVATE -Werror=return-type)
    endif()
endfunction()

function(hitbox_add_lab name)
    cmake_parse_arguments(PARSE_ARGV 1 LAB "" "MAIN" "SOURCES")
    if(NOT LAB_MAIN OR NOT LAB_SOURCES)
        message(FATAL_ERROR "hitbox_add_lab(${name} MAIN <main.cpp> SOURCES <files...>): "
                            "give the main file and at least one source")
    endif()
    if(LAB_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "hitbox_add_lab(${name}): unknown arguments ${LAB_UNPARSED_ARGUMENTS}")
    endif()
    set(lab_dir "${CMAKE_CURRENT_SOURCE_DIR}")
    get_property(handout GLOBAL PROPERTY HITBOX_LAB_HANDOUT)
    get_property(generator GLOBAL PROPERTY HITBOX_LAB_GENERATOR)

    # The solution (or, in a handout, the student's code): the sources as they are.
    add_library(${name}_level STATIC ${LAB_SOURCES})
    target_include_directories(${name}_level PUBLIC "${lab_dir}")
    target_link_libraries(${name}_level PUBLIC hitbox)
    _hitbox_lab_target_settings(${name}_level)
    add_executable(${name} ${LAB_MAIN})
    target_link_libraries(${name} PRIVATE ${name}_level)
    _hitbox_lab_target_settings(${name})
    if(handout)
        return()
    endif()

    # The exercise: each file regenerated whenever its solution file (or the generator)
    # changes. The folder layout is kept, so the lab's own includes find each other.
    set(exercise_dir "${CMAKE_CURRENT_BINARY_DIR}/exercise")
    set(exercise_sources "")
    set(exercise_main "")
    foreach(source IN LISTS LAB_SOURCES LAB_MAIN)
        get_filename_component(source_path "${source}" ABSOLUTE BASE_DIR "${lab_dir}")
        file(RELATIVE_PATH relative "${lab_dir}" "${source_path}")
        set(exercise_file "${exercise_dir}/${relative}")
        add_custom_command(OUTPUT "${exercise_file}"
            COMMAND "${CMAKE_COMMAND}" "-DINPUT=${source_path}" "-DOUTPUT=${exercise_file}"
                    -P "${generator}"
            DEPENDS "${source_path}" "${generator}"
            COMMENT "Writing the exercise version of ${name}/${relative}"
            VERBATIM)
        if(source STREQUAL LAB_MAIN)
            set(exercise_main "${exercise_file}")
        else()
            list(APPEND exercise_sources "${exercise_file}")
        endif()
    endforeach()

    add_library(${name}_exercise_level STATIC ${exercise_sources})
    target_include_directories(${name}_exercise_level PUBLIC "${exercise_dir}")
    target_link_libraries(${name}_exercise_level PUBLIC hitbox)
    _hitbox_lab_target_settings(${name}_exercise_level)
    add_executable(${name}_exercise ${exercise_main})
    target_link_libraries(${name}_exercise PRIVATE ${name}_exercise_level)
    _hitbox_lab_target_settings(${name}_exercise)
endfunction()

# The path of the lab's program, for a failing scene test's replay (tests/support/
# SceneReplay.h), in a generated LabProgram.h rather than a compile definition: a definition
# holding an absolute path makes every test source's command differ between two checkouts,
# so ccache could not reuse one compiled in another (the handout, CI's clone). Now only the
# sources that include SceneReplay.h differ.
function(_hitbox_lab_program_header tests program)
    set(folder "${CMAKE_CURRENT_BINARY_DIR}/${tests}_program/$<CONFIG>")
    file(GENERATE OUTPUT "${folder}/LabProgram.h"
        CONTENT "#define HITBOX_LAB_PROGRAM \"$<TARGET_FILE:${program}>\"\n")
    target_include_directories(${tests} PRIVATE "${folder}")
endfunction()

function(hitbox_add_lab_tests name)
    cmake_parse_arguments(PARSE_ARGV 1 LAB "" "" "SOURCES")
    if(NOT LAB_SOURCES)
        message(FATAL_ERROR "hitbox_add_lab_tests(${name} SOURCES <files...>): give the test sources")
    endif()
    if(NOT TARGET ${name}_level)
        message(WARNING "hitbox_add_lab_tests(${name}): there is no lab ${name} "
                        "(no hitbox_add_lab(${name} ...) in labs/); its tests are skipped")
        return()
    endif()

    # The instructor's hidden variants (tests/labs-hidden/NN_name/*.cpp, not in the handout).
    get_filename_component(lab_folder "${CMAKE_CURRENT_SOURCE_DIR}" NAME)
    file(GLOB hidden_sources CONFIGURE_DEPENDS
        "${PROJECT_SOURCE_DIR}/tests/labs-hidden/${lab_folder}/*.cpp")
    list(APPEND LAB_SOURCES ${hidden_sources})

    add_executable(${name}_tests ${LAB_SOURCES})
    target_link_libraries(${name}_tests PRIVATE ${name}_level hitbox_test_support)
    _hitbox_lab_target_settings(${name}_tests)
    # The program a failing scene test's replay opens in (tests/support/SceneReplay.h).
    _hitbox_lab_program_header(${name}_tests ${name})
    gtest_discover_tests(${name}_tests
        TEST_PREFIX "${name}."
        DISCOVERY_TIMEOUT 60
        PROPERTIES LABELS lab ENVIRONMENT "ALSOFT_DRIVERS=null")
    get_property(handout GLOBAL PROPERTY HITBOX_LAB_HANDOUT)
    if(handout)
        return()
    endif()

    # The same tests against the exercise. Not a ctest test: most of them fail on purpose.
    add_executable(${name}_exercise_tests ${LAB_SOURCES})
    target_link_libraries(${name}_exercise_tests PRIVATE ${name}_exercise_level hitbox_test_support)
    _hitbox_lab_target_settings(${name}_exercise_tests)
    _hitbox_lab_program_header(${name}_exercise_tests ${name}_exercise)
endfunction()

# Adds every numbered folder NN_name/ of the current source folder that has a
# CMakeLists.txt, in order: used by labs/ (the lab programs) and tests/labs/ (their tests).
function(hitbox_add_lab_folders)
    file(GLOB lab_folders LIST_DIRECTORIES true RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}"
        CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/[0-9][0-9]_*")
    list(SORT lab_folders)
    foreach(lab_folder IN LISTS lab_folders)
        if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${lab_folder}/CMakeLists.txt")
            add_subdirectory(${lab_folder})
        endif()
    endforeach()
endfunction()
