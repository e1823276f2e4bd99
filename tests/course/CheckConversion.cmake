# Converts one course lab file with HitboxConvertCourseSource.cmake and checks what a
# compiler needs: UTF-8 with no byte-order mark or NUL bytes, includes with forward
# slashes, the #line directive naming the original, and the code itself unchanged.
# Usage: cmake -DCONVERTER=... -DINPUT=... -DOUTPUT=... -P CheckConversion.cmake
execute_process(COMMAND "${CMAKE_COMMAND}" -DINPUT=${INPUT} -DOUTPUT=${OUTPUT} -P "${CONVERTER}"
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the converter failed on ${INPUT}")
endif()

file(READ "${OUTPUT}" start_hex LIMIT 3 HEX)
if(start_hex STREQUAL "efbbbf")
    message(FATAL_ERROR "${OUTPUT} still starts with a byte-order mark")
endif()
file(READ "${OUTPUT}" content_hex HEX)
string(REGEX MATCH "^(..)*00" nul_byte "${content_hex}")
if(nul_byte)
    message(FATAL_ERROR "${OUTPUT} still holds NUL bytes: UTF-16 was not converted")
endif()

file(READ "${OUTPUT}" converted)
file(TO_CMAKE_PATH "${INPUT}" original_path)
if(NOT converted MATCHES "^#line 1 \"${original_path}\"\n")
    message(FATAL_ERROR "${OUTPUT} does not start with #line 1 naming ${INPUT}")
endif()
if(converted MATCHES "#[ \t]*include[ \t]*[\"<][^\"<>\n]*\\\\")
    message(FATAL_ERROR "${OUTPUT} still has an include written with a backslash")
endif()
if(NOT converted MATCHES "#include \"Level.h\"|#include \"Framework/BaseLevel.h\"")
    message(FATAL_ERROR "${OUTPUT} lost its includes")
endif()
if(converted MATCHES "Main.cpp" AND NOT converted MATCHES "int main\\(\\)")
    message(FATAL_ERROR "${OUTPUT}: main() is missing after conversion")
endif()
message(STATUS "${INPUT} converted correctly")
