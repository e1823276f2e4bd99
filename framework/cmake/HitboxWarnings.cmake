# hitbox_warnings(target [AS_ERRORS ON|OFF]): the settings every Hitbox target is built with.
#  - Warnings: /W4 /permissive- (MSVC), -Wall -Wextra -Wpedantic (GCC, Clang); errors when
#    AS_ERRORS is ON (default: HITBOX_WARNINGS_AS_ERRORS). Lab code passes its own AS_ERRORS.
#  - /utf-8 on MSVC: the sources are UTF-8 (a "π" in a comment, the "—" the exercise
#    generator writes), and without it MSVC reads them in the system's code page: warning
#    C4819 on East-Asian Windows, an error under /WX.
#  - A program gets the DLLs it needs copied next to it (hitbox_copy_runtime_dlls, below).
function(hitbox_warnings target)
    cmake_parse_arguments(PARSE_ARGV 1 HITBOX "" "AS_ERRORS" "")
    if(NOT DEFINED HITBOX_AS_ERRORS)
        set(HITBOX_AS_ERRORS ${HITBOX_WARNINGS_AS_ERRORS})
    endif()
    if(MSVC)
        target_compile_options(${target} PRIVATE /W4 /permissive-)
        if(HITBOX_AS_ERRORS)
            target_compile_options(${target} PRIVATE /WX)
        endif()
    else()
        target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
        if(HITBOX_AS_ERRORS)
            target_compile_options(${target} PRIVATE -Werror)
        endif()
    endif()
    hitbox_portable_settings(${target})
endfunction()

# hitbox_portable_settings(target): what every compiler needs to build and run `target`,
# whatever its warnings (course labs use this alone): /utf-8 on MSVC, SFML's DLLs.
function(hitbox_portable_settings target)
    if(MSVC)
        target_compile_options(${target} PRIVATE /utf-8)
    endif()
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "EXECUTABLE")
        hitbox_copy_runtime_dlls(${target})
    endif()
endfunction()

# hitbox_copy_runtime_dlls(program): on Windows, copies the DLLs `program` needs to start next
# to it after each build (SFML's, when SFML is built shared, as SFML 2.6 is by default;
# GoogleTest's when it is shared; SFML 2's openal32.dll, HITBOX_OPENAL_DLL from
# HitboxSFML.cmake), so it starts from Visual Studio (F5), from Explorer, and for test
# discovery, which runs each test program right after it is built.
function(hitbox_copy_runtime_dlls program)
    if(NOT WIN32)
        return()
    endif()
    if(HITBOX_OPENAL_DLL)
        add_custom_command(TARGET ${program} POST_BUILD
            COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${HITBOX_OPENAL_DLL}"
                    "$<TARGET_FILE_DIR:${program}>"
            VERBATIM)
    endif()
    if(CMAKE_VERSION VERSION_LESS 3.21)
        message(WARNING "CMake ${CMAKE_VERSION} cannot list ${program}'s DLLs (3.21 can): "
                        "copy SFML's DLLs next to it yourself, or install a newer CMake")
        return()
    endif()
    # $<TARGET_RUNTIME_DLLS> is empty when everything is static, and `cmake -E copy` with
    # nothing to copy is an error: then the command is `cmake -E true`.
    set(dlls "$<TARGET_RUNTIME_DLLS:${program}>")
    set(copy "${CMAKE_COMMAND};-E;copy_if_different;${dlls};$<TARGET_FILE_DIR:${program}>")
    add_custom_command(TARGET ${program} POST_BUILD
        COMMAND "$<IF:$<BOOL:${dlls}>,${copy},${CMAKE_COMMAND};-E;true>"
        COMMAND_EXPAND_LISTS
        VERBATIM)
endfunction()
