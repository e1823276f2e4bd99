# The switch the lab 2 and lab 3 sheets offer ("Using your own Collision class from lab 0")
# proved: each lab built with its one call changed, `hitbox::Collision::` to `MyCollision::` in
# the pair test, passes its own grading tests with lab 0's solution plugged in. One ctest
# test a lab: lab00_own_collision.in_<lab>.PassesItsGradingTests. Never in the handout
# (there the lab files are the student's own).
#
# lab_with_own_collision(<lab> <folder> <file> <call> <tests>...): <file> of labs/<folder>
# is copied
# (configure time) with `hitbox::Collision::<call>` made `MyCollision::<call>`; the build stops if
# the call is no longer there, so the check can never silently test the unchanged lab. The
# <tests> are tests/labs/<folder>'s sources (and the hidden variants are added).
function(lab_with_own_collision lab folder file call)
    set(tests ${ARGN})
    if(NOT TARGET ${lab}_level)
        return()
    endif()
    set(lab_dir "${PROJECT_SOURCE_DIR}/labs/${folder}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${lab_dir}/${file}")
    file(READ "${lab_dir}/${file}" text)
    string(FIND "${text}" "hitbox::Collision::${call}(" where)
    if(where EQUAL -1)
        message(FATAL_ERROR "lab_with_own_collision: ${lab_dir}/${file} no longer calls "
                            "hitbox::Collision::${call}; update its sheet and this check")
    endif()
    string(REGEX REPLACE "([^A-Za-z_:])hitbox::Collision::${call}\\(" "\\1MyCollision::${call}("
           switched "${text}")
    set(switched_file "${CMAKE_CURRENT_BINARY_DIR}/in_${lab}/${file}")
    file(CONFIGURE OUTPUT "${switched_file}" CONTENT "${switched}" @ONLY)

    # The lab's own sources, with the one file switched.
    get_target_property(sources ${lab}_level SOURCES)
    set(variant_sources "")
    foreach(source IN LISTS sources)
        if(source STREQUAL file)
            list(APPEND variant_sources "${switched_file}")
        else()
            list(APPEND variant_sources "${lab_dir}/${source}")
        endif()
    endforeach()
    list(TRANSFORM tests PREPEND "${PROJECT_SOURCE_DIR}/tests/labs/${folder}/")
    file(GLOB hidden_tests CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/tests/labs-hidden/${folder}/*.cpp")
    add_executable(${lab}_own_collision_tests ${variant_sources} ${tests} ${hidden_tests})
    target_include_directories(${lab}_own_collision_tests PRIVATE "${lab_dir}")
    target_link_libraries(${lab}_own_collision_tests PRIVATE lab00_own_collision_level
                                                             hitbox_test_support)
    hitbox_warnings(${lab}_own_collision_tests)
    add_test(NAME lab00_own_collision.in_${lab}.PassesItsGradingTests
        COMMAND ${lab}_own_collision_tests)
    set_tests_properties(lab00_own_collision.in_${lab}.PassesItsGradingTests PROPERTIES
        LABELS lab ENVIRONMENT "ALSOFT_DRIVERS=null")
endfunction()

lab_with_own_collision(lab02_bouncing_balls 02_bouncing_balls BallsLevel.cpp checkBoundingCircle
    BallsGradingTests.cpp)
lab_with_own_collision(lab03_bouncing_squares 03_bouncing_squares Square.cpp checkBoundingBox
    SquaresGradingTests.cpp)
