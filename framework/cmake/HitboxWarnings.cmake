# hitbox_warnings(target [AS_ERRORS ON|OFF]): the settings every Hitbox target is built with.
#  - Warnings: /W4 /permissive- (MSVC), -Wall -Wextra -Wpedantic (GCC, Clang); errors when
#    AS_ERRORS is ON (default: HITBOX_WARNINGS_AS_ERRORS). Lab code passes its own AS_ERRORS.
#  - /utf-8 on MSVC: the sources are UTF-8 (a "π" in a comment, the "—" the exercise
#    generator writes), and without it MSVC reads them in the system's code page: warning
#    C4819 on East-Asian Windows, an error under /WX.
#  - A program gets SFML's DLLs copied next to it (hitbox_copy_runtime_dlls, HitboxSFML.cmake).
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
    if(type STREQUAL "EXECUTABLE" AND COMMAND hitbox_copy_runtime_dlls)
        hitbox_copy_runtime_dlls(${target})
    endif()
endfunction()
