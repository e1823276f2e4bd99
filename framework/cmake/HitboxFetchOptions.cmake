# hitbox_fetch_options(<var>): the options every FetchContent_Declare of a dependency gets,
# where this CMake has them: SYSTEM (3.25), so the dependency's headers never warn in our
# code, and EXCLUDE_FROM_ALL (3.28), so only the parts Hitbox links are built.
function(hitbox_fetch_options var)
    set(options "")
    if(CMAKE_VERSION VERSION_GREATER_EQUAL 3.28)
        list(APPEND options EXCLUDE_FROM_ALL)
    endif()
    if(CMAKE_VERSION VERSION_GREATER_EQUAL 3.25)
        list(APPEND options SYSTEM)
    endif()
    set(${var} ${options} PARENT_SCOPE)
endfunction()
