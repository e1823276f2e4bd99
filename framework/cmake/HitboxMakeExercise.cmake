# Writes the student (exercise) version of one lab source file from the solution.
#
# The grammar's one home is scripts/labtool/markers.py (make_exercise() there writes the same
# text); this file is its CMake twin so the build needs no Python, and `python3 scripts/lab.py
# same-exercise` (CI, scripts/check-grading.sh) proves the two agree on every lab file.
#
# The solution marks what a student writes:
#
#     // BEGIN TASK 2: bounce off the window edges
#     ...solution lines (dropped)...
#     // STARTER TASK 2                       (optional)
#     // ...starter lines, written as comments: "// " is removed from each...
#     // END TASK 2
#
# and the exercise gets, in their place, at the indentation of the BEGIN line:
#
#     // TASK 2: bounce off the window edges — see README.md
#     ...starter lines, un-commented...
#
# Everything else, slide markers included, is copied as it is. Markers that do not pair up
# stop the build with the file and line, so a mistake never ships a half-hidden solution.
#
# Usage (CMake script mode, works on every OS):
#   cmake -DINPUT=<solution file> -DOUTPUT=<exercise file> -P HitboxMakeExercise.cmake
# Optional:
#   -DSOLVED_TASKS=1,3   keep these tasks' solutions (markers and starters removed): what a
#                        student's file looks like after finishing them (check-handout.sh)
cmake_minimum_required(VERSION 3.16)

if(NOT INPUT OR NOT OUTPUT)
    message(FATAL_ERROR
        "usage: cmake -DINPUT=<file> -DOUTPUT=<file> [-DSOLVED_TASKS=1,2] -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
if(NOT EXISTS "${INPUT}")
    message(FATAL_ERROR "${INPUT}: file not found")
endif()
string(REPLACE "," ";" solved_tasks "${SOLVED_TASKS}")

# The file is read whole and cut at each newline with string(FIND): no CMake list ever holds
# a line, so `;`, `[`, `]` and `\` in the C++ source come through untouched.
file(READ "${INPUT}" content)
set(output "")
set(state "code") # code | solution | starter
set(task "")
set(begin_line 0)
set(line_number 0)
set(marker_regex "^[ \t]*//[ \t]*(BEGIN|STARTER|END)[ \t]+TASK")

while(NOT content STREQUAL "")
    string(FIND "${content}" "\n" newline)
    if(newline EQUAL -1)
        set(line "${content}")
        set(content "")
        set(ending "")
    else()
        string(SUBSTRING "${content}" 0 ${newline} line)
        math(EXPR rest_start "${newline} + 1")
        string(SUBSTRING "${content}" ${rest_start} -1 content)
        set(ending "\n")
    endif()
    math(EXPR line_number "${line_number} + 1")
    set(where "${INPUT}:${line_number}")
    # Windows line ends (file(READ) may keep a \r): match markers without it.
    string(REGEX REPLACE "\r$" "" bare "${line}")

    if(bare MATCHES "${marker_regex}")
        if(bare MATCHES "^([ \t]*)//[ \t]*BEGIN TASK ([0-9]+):[ \t]*([^ \t].*)$")
            set(indent "${CMAKE_MATCH_1}")
            set(number "${CMAKE_MATCH_2}")
            set(title "${CMAKE_MATCH_3}")
            if(NOT state STREQUAL "code")
                message(FATAL_ERROR "${where}: BEGIN TASK ${number} inside TASK ${task} "
                                    "(opened at line ${begin_line}); close it with // END TASK ${task} first")
            endif()
            set(state "solution")
            set(task "${number}")
            set(begin_line ${line_number})
            list(FIND solved_tasks "${number}" solved_index)
            if(solved_index EQUAL -1)
                set(solved FALSE)
                string(APPEND output "${indent}// TASK ${number}: ${title} — see README.md${ending}")
            else()
                set(solved TRUE)
            endif()
        elseif(bare MATCHES "^[ \t]*//[ \t]*STARTER TASK ([0-9]+)[ \t]*$")
            if(NOT state STREQUAL "solution" OR NOT CMAKE_MATCH_1 STREQUAL task)
                message(FATAL_ERROR "${where}: STARTER TASK ${CMAKE_MATCH_1} must come after "
                                    "// BEGIN TASK ${CMAKE_MATCH_1} and before its // END TASK")
            endif()
            set(state "starter")
        elseif(bare MATCHES "^[ \t]*//[ \t]*END TASK ([0-9]+)[ \t]*$")
            if(state STREQUAL "code" OR NOT CMAKE_MATCH_1 STREQUAL task)
                if(state STREQUAL "code")
                    message(FATAL_ERROR "${where}: END TASK ${CMAKE_MATCH_1} without a BEGIN TASK ${CMAKE_MATCH_1}")
                endif()
                message(FATAL_ERROR "${where}: END TASK ${CMAKE_MATCH_1} closes TASK ${task} "
                                    "(opened at line ${begin_line}); expected // END TASK ${task}")
            endif()
            set(state "code")
        else()
            message(FATAL_ERROR "${where}: malformed task marker: ${bare}\n"
                                "Write // BEGIN TASK <n>: <title>, // STARTER TASK <n> or // END TASK <n>")
        endif()
    elseif(state STREQUAL "code")
        string(APPEND output "${line}${ending}")
    elseif(state STREQUAL "solution")
        if(solved)
            string(APPEND output "${line}${ending}")
        endif()
    else() # starter: each line is a comment; remove the first "// " after the indentation
        if(bare MATCHES "^[ \t]*$")
            set(starter_line "${line}")
        elseif(bare MATCHES "^([ \t]*)// ?(.*)$")
            set(starter_line "${CMAKE_MATCH_1}${CMAKE_MATCH_2}")
            if(CMAKE_MATCH_2 STREQUAL "")
                set(starter_line "") # a bare "//" is an empty line, without trailing blanks
            endif()
        else()
            message(FATAL_ERROR "${where}: a starter line of TASK ${task} must be a comment "
                                "(\"// \" + the code the student starts from): ${bare}")
        endif()
        if(NOT solved)
            string(APPEND output "${starter_line}${ending}")
        endif()
    endif()
endwhile()

if(NOT state STREQUAL "code")
    message(FATAL_ERROR "${INPUT}:${begin_line}: BEGIN TASK ${task} is never closed "
                        "(add // END TASK ${task})")
endif()

# Rewrite only when the text changed, so an unchanged exercise file does not recompile.
if(EXISTS "${OUTPUT}")
    file(READ "${OUTPUT}" previous)
    if(previous STREQUAL output)
        return()
    endif()
endif()
file(WRITE "${OUTPUT}" "${output}")
