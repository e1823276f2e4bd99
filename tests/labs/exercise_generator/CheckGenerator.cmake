# Runs HitboxMakeExercise.cmake on one input and compares the result with the expected
# file byte for byte. Usage:
#   cmake -DGENERATOR=... -DINPUT=... -DEXPECTED=... -DOUTPUT=... -P CheckGenerator.cmake
execute_process(
    COMMAND "${CMAKE_COMMAND}" "-DINPUT=${INPUT}" "-DOUTPUT=${OUTPUT}" -P "${GENERATOR}"
    RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "the generator failed on ${INPUT}:\n${errors}")
endif()
file(READ "${OUTPUT}" actual)
file(READ "${EXPECTED}" expected)
if(NOT actual STREQUAL expected)
    message(FATAL_ERROR "${OUTPUT} differs from ${EXPECTED}:\n--- got ---\n${actual}--- expected ---\n${expected}")
endif()
message(STATUS "exercise generator: ${OUTPUT} is as expected")
