# Converts one course lab file with HitboxConvertCourseSource.cmake and checks that the
# result matches EXPECT (a regular expression) and, with NO_BYTE_ORDER_MARK, holds no UTF-8
# byte-order mark anywhere.
# Usage: cmake -DCONVERTER=... -DINPUT=... -DOUTPUT=... -DLAB_DIR=... -DSEARCH_DIRS=...
#              "-DEXPECT=<regex>" [-DNO_BYTE_ORDER_MARK=ON] -P CheckConvertedText.cmake
execute_process(COMMAND "${CMAKE_COMMAND}" -DINPUT=${INPUT} -DOUTPUT=${OUTPUT}
    -DLAB_DIR=${LAB_DIR} -DSEARCH_DIRS=${SEARCH_DIRS} -P "${CONVERTER}"
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the converter failed on ${INPUT}")
endif()
file(READ "${OUTPUT}" converted)
if(NOT converted MATCHES "${EXPECT}")
    message(FATAL_ERROR "${OUTPUT} does not match ${EXPECT}:\n${converted}")
endif()
file(READ "${OUTPUT}" converted_hex HEX)
if(NO_BYTE_ORDER_MARK AND converted_hex MATCHES "^(..)*efbbbf")
    message(FATAL_ERROR "${OUTPUT} still holds a UTF-8 byte-order mark")
endif()
message(STATUS "${INPUT} converted as expected")
