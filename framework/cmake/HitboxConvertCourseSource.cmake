# Copies one source file of a course lab folder into the build tree so that g++ and clang
# can read it, the way Visual Studio reads the original:
#   - UTF-16 (Visual Studio's "Unicode" save, with or without its byte-order mark) becomes
#     UTF-8; a UTF-8 byte-order mark is dropped (g++ accepts one only at the very start of a
#     file, and the #line below comes first).
#   - Include lines written with Windows backslashes (#include "Framework\GameObject.h")
#     get forward slashes, which every compiler accepts.
#   - Windows finds files whatever their letter case: an include that names no file as
#     written is rewritten to the file it names when letter case is ignored: the lab's own
#     file first ("player.h" is Player.h), else the standard header of that name ("Vector"
#     and <String> are <vector> and <string>), else Hitbox's course header in SEARCH_DIRS.
#   - A #line directive names the original file, so compiler errors point at the file the
#     student edits, not at this copy.
# Only these changes are made: line numbers stay the same.
#
# Usage (CMake script mode, works on every OS):
#   cmake -DINPUT=<lab>/Main.cpp -DOUTPUT=<build>/Main.cpp [-DLAB_DIR=<lab>]
#         [-DSEARCH_DIRS=<dir>;<dir>] -P HitboxConvertCourseSource.cmake
cmake_minimum_required(VERSION 3.16)

if(NOT INPUT OR NOT OUTPUT)
    message(FATAL_ERROR "usage: cmake -DINPUT=<file> -DOUTPUT=<file> -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
if(NOT EXISTS "${INPUT}")
    message(FATAL_ERROR "${INPUT}: file not found (was it deleted? re-run cmake to refresh the list)")
endif()

# Appends the UTF-8 bytes of one Unicode code point to the variable named by `out_var`.
function(hitbox_append_utf8 out_var code_point)
    if(code_point LESS 128)
        string(ASCII ${code_point} chars)
    elseif(code_point LESS 2048)
        math(EXPR b1 "192 + (${code_point} >> 6)")
        math(EXPR b2 "128 + (${code_point} & 63)")
        string(ASCII ${b1} ${b2} chars)
    elseif(code_point LESS 65536)
        math(EXPR b1 "224 + (${code_point} >> 12)")
        math(EXPR b2 "128 + ((${code_point} >> 6) & 63)")
        math(EXPR b3 "128 + (${code_point} & 63)")
        string(ASCII ${b1} ${b2} ${b3} chars)
    else()
        math(EXPR b1 "240 + (${code_point} >> 18)")
        math(EXPR b2 "128 + ((${code_point} >> 12) & 63)")
        math(EXPR b3 "128 + ((${code_point} >> 6) & 63)")
        math(EXPR b4 "128 + (${code_point} & 63)")
        string(ASCII ${b1} ${b2} ${b3} ${b4} chars)
    endif()
    set(${out_var} "${${out_var}}${chars}" PARENT_SCOPE)
endfunction()

# Decodes UTF-16 given as a hex string (two hex digits per byte, no byte-order mark).
# `little_endian` is TRUE for UTF-16LE (Windows), FALSE for UTF-16BE.
function(hitbox_utf16_hex_to_utf8 out_var hex little_endian)
    string(LENGTH "${hex}" hex_length)
    set(text "")
    set(high_surrogate 0)
    set(position 0)
    while(position LESS hex_length)
        string(SUBSTRING "${hex}" ${position} 2 first_byte)
        math(EXPR second_position "${position} + 2")
        string(SUBSTRING "${hex}" ${second_position} 2 second_byte)
        math(EXPR position "${position} + 4")
        if(little_endian)
            math(EXPR unit "0x${second_byte}${first_byte}")
        else()
            math(EXPR unit "0x${first_byte}${second_byte}")
        endif()

        if(unit EQUAL 0)
            # A NUL character cannot be part of C++ source text; leave it out.
        elseif(unit GREATER_EQUAL 55296 AND unit LESS 56320) # 0xD800-0xDBFF: first half of a pair
            set(high_surrogate ${unit})
        elseif(unit GREATER_EQUAL 56320 AND unit LESS 57344) # 0xDC00-0xDFFF: second half
            if(high_surrogate)
                math(EXPR code_point "65536 + ((${high_surrogate} - 55296) << 10) + (${unit} - 56320)")
                hitbox_append_utf8(text ${code_point})
            endif()
            set(high_surrogate 0)
        else()
            hitbox_append_utf8(text ${unit})
        endif()
    endwhile()
    set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# Read the file and decide its encoding from the byte-order mark (or, without one, from a
# zero byte in the first character, which plain text never has).
file(READ "${INPUT}" start_hex LIMIT 4 HEX)
string(TOLOWER "${start_hex}" start_hex)
set(utf16 FALSE)
set(utf8_skip_bytes 0)
if(start_hex MATCHES "^efbbbf")
    set(utf8_skip_bytes 3) # UTF-8 with a byte-order mark ("UTF-8 with signature")
elseif(start_hex MATCHES "^fffe")
    set(utf16 TRUE)
    set(little_endian TRUE)
    set(skip_bytes 2)
elseif(start_hex MATCHES "^feff")
    set(utf16 TRUE)
    set(little_endian FALSE)
    set(skip_bytes 2)
elseif(start_hex MATCHES "^[0-7][0-9a-f]00")
    set(utf16 TRUE)
    set(little_endian TRUE)
    set(skip_bytes 0)
elseif(start_hex MATCHES "^00[0-7][0-9a-f]")
    set(utf16 TRUE)
    set(little_endian FALSE)
    set(skip_bytes 0)
endif()

if(utf16)
    file(READ "${INPUT}" content_hex OFFSET ${skip_bytes} HEX)
    string(TOLOWER "${content_hex}" content_hex)
    hitbox_utf16_hex_to_utf8(content "${content_hex}" ${little_endian})
else()
    file(READ "${INPUT}" content OFFSET ${utf8_skip_bytes})
endif()

# Backslashes in include lines become forward slashes. Only the include lines change:
# a backslash anywhere else (a string literal, a line continuation) is left alone.
string(REGEX MATCHALL "#[ \t]*include[ \t]*[\"<][^\"<>\r\n]*[\">]" include_lines "${content}")
list(REMOVE_DUPLICATES include_lines)
foreach(include_line IN LISTS include_lines)
    if(include_line MATCHES "\\\\")
        string(REPLACE "\\" "/" fixed_line "${include_line}")
        string(REPLACE "${include_line}" "${fixed_line}" content "${content}")
    endif()
endforeach()

# Headers a lab may spell in any letter case, because Windows finds them whatever the case:
# the C++17 standard library's (and the C headers it keeps), and <windows.h>, for which
# Hitbox has a stand-in on Linux and macOS (framework/compat/windows/windows.h).
set(system_headers
    algorithm any array atomic bitset cassert cctype cerrno cfloat charconv chrono cinttypes
    climits clocale cmath codecvt complex condition_variable csetjmp csignal cstdarg cstddef
    cstdint cstdio cstdlib cstring ctime cwchar cwctype deque exception execution filesystem
    forward_list fstream functional future initializer_list iomanip ios iosfwd iostream
    istream iterator limits list locale map memory memory_resource mutex new numeric
    optional ostream queue random ratio regex scoped_allocator set shared_mutex sstream stack
    stdexcept streambuf string string_view system_error thread tuple type_traits typeindex
    typeinfo unordered_map unordered_set utility valarray variant vector
    assert.h ctype.h float.h limits.h math.h stddef.h stdint.h stdio.h stdlib.h string.h
    time.h windows.h)

# <String>, <Vector>, <Windows.h>: a system header in other letter case gets its own.
string(REGEX MATCHALL "#[ \t]*include[ \t]*<[^<>\r\n]*>" angle_includes "${content}")
list(REMOVE_DUPLICATES angle_includes)
foreach(include_line IN LISTS angle_includes)
    string(REGEX REPLACE "^.*<(.*)>$" "\\1" named "${include_line}")
    string(TOLOWER "${named}" lower_named)
    if(NOT named STREQUAL lower_named AND lower_named IN_LIST system_headers)
        string(REPLACE "<${named}>" "<${lower_named}>" fixed_line "${include_line}")
        string(REPLACE "${include_line}" "${fixed_line}" content "${content}")
    endif()
endforeach()

# Finds, ignoring letter case, the header under one of `dirs` that `wanted` (lower case)
# names, with `suffix` added to it; sets `out_var` to its path as spelled, or "". In the
# lab's own folders, its Framework/ and SFML/ copies are not looked at: Hitbox replaces them
# (its own GameState.h has the same spelling as Hitbox's).
function(hitbox_find_header_ignoring_case out_var wanted suffix dirs)
    foreach(dir IN LISTS dirs)
        file(GLOB_RECURSE candidates RELATIVE "${dir}" "${dir}/*.h" "${dir}/*.hpp")
        foreach(candidate IN LISTS candidates)
            string(TOLOWER "${candidate}" lower_candidate)
            if(dir IN_LIST own_dirs AND lower_candidate MATCHES "^(framework|sfml)/")
                continue()
            endif()
            if(lower_candidate STREQUAL "${wanted}${suffix}")
                set(${out_var} "${candidate}" PARENT_SCOPE)
                return()
            endif()
        endforeach()
    endforeach()
    set(${out_var} "" PARENT_SCOPE)
endfunction()

# Letter case in quoted includes. An include that names no file as written is resolved the
# way Visual Studio's search on a case-blind file system would find it: first the lab's own
# files (beside the including file, then in the lab folder: "player.h" is Player.h), then
# a standard header of that name ("Vector" is <vector>, not the course's Vector.h), then
# Hitbox's course headers in SEARCH_DIRS ("Framework/tilemap.h"). Last, for old labs that
# wrote "Framework/GameObject" without its extension, the same with ".h" added.
get_filename_component(input_dir "${INPUT}" DIRECTORY)
set(own_dirs "${input_dir}")
if(LAB_DIR)
    list(APPEND own_dirs "${LAB_DIR}")
endif()
set(search_dirs ${own_dirs} ${SEARCH_DIRS})
string(REGEX MATCHALL "#[ \t]*include[ \t]*\"[^\"\r\n]*\"" quoted_includes "${content}")
list(REMOVE_DUPLICATES quoted_includes)
foreach(include_line IN LISTS quoted_includes)
    string(REGEX REPLACE "^.*\"(.*)\"$" "\\1" named "${include_line}")
    set(as_written FALSE)
    foreach(dir IN LISTS search_dirs)
        if(EXISTS "${dir}/${named}" AND NOT IS_DIRECTORY "${dir}/${named}")
            set(as_written TRUE)
            break()
        endif()
    endforeach()
    if(as_written)
        continue()
    endif()
    string(TOLOWER "${named}" wanted)
    set(replacement "")
    hitbox_find_header_ignoring_case(found "${wanted}" "" "${own_dirs}")
    if(found)
        set(replacement "\"${found}\"")
    elseif(wanted IN_LIST system_headers)
        set(replacement "<${wanted}>")
    else()
        hitbox_find_header_ignoring_case(found "${wanted}" "" "${SEARCH_DIRS}")
        if(NOT found)
            hitbox_find_header_ignoring_case(found "${wanted}" ".h" "${search_dirs}")
        endif()
        if(found)
            set(replacement "\"${found}\"")
        endif()
    endif()
    if(replacement)
        string(REPLACE "\"${named}\"" "${replacement}" fixed_line "${include_line}")
        string(REPLACE "${include_line}" "${fixed_line}" content "${content}")
    endif()
endforeach()

file(TO_CMAKE_PATH "${INPUT}" original_path)
file(WRITE "${OUTPUT}" "#line 1 \"${original_path}\"\n${content}")
