# Run as a script (cmake -P) by the build: fails when a file of one layer includes a layer it
# may not use. Called by hitbox_layer() in framework/CMakeLists.txt with:
#   LAYER    the layer's name (geometry, broadphase, ...)
#   ALLOWED  ";"-separated layers this one may include (its own is always allowed)
#   NO_SFML  ON when the layer must not include SFML at all
#   FILES    ";"-separated files to read
#   STAMP    the file to touch when every include is allowed
#   ROOT     framework/ (optional): also refuse a forward declaration (`class Input;`) of a
#            type that a layer this one may not use defines (or compat/ does): it would get
#            past the include check. No exceptions.
cmake_minimum_required(VERSION 3.16)
set(problems "")

# The classes and structs each other layer defines (a definition: `class Name` not followed
# by `;`), and compat/'s, as "Name" -> layer in variables defined_in_<Name>.
set(foreign_types "")
set(usable_types "")
if(ROOT)
    file(GLOB layer_dirs LIST_DIRECTORIES true "${ROOT}/hitbox/*")
    foreach(dir IN LISTS layer_dirs "${ROOT}/compat")
        get_filename_component(other "${dir}" NAME)
        if(NOT IS_DIRECTORY "${dir}")
            continue()
        endif()
        file(GLOB_RECURSE headers "${dir}/*.h")
        foreach(header IN LISTS headers)
            file(STRINGS "${header}" definitions REGEX "^(class|struct)[ \t]+[A-Za-z_][A-Za-z0-9_]*[ \t]*([:{]|$)")
            foreach(definition IN LISTS definitions)
                string(REGEX REPLACE "^(class|struct)[ \t]+([A-Za-z_][A-Za-z0-9_]*).*$" "\\2" name "${definition}")
                if(other STREQUAL LAYER OR other IN_LIST ALLOWED)
                    list(APPEND usable_types "${name}")
                elseif(NOT DEFINED defined_in_${name}) # hitbox/'s layers before compat/
                    set(defined_in_${name} "${other}")
                    list(APPEND foreign_types "${name}")
                endif()
            endforeach()
        endforeach()
    endforeach()
    # A name this layer may use (compat's course2025 GameObject shares the objects layer's
    # name) is never foreign.
    if(usable_types)
        list(REMOVE_ITEM foreign_types ${usable_types})
    endif()
endif()
foreach(file IN LISTS FILES)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS includes)
        if(line MATCHES "[<\"]hitbox/([a-z]+)/")
            set(used "${CMAKE_MATCH_1}")
            if(NOT used STREQUAL LAYER AND NOT used IN_LIST ALLOWED)
                string(APPEND problems "  ${file}: ${line}\n")
            endif()
            if(line MATCHES "hitbox/app/private/" AND NOT LAYER STREQUAL "app")
                string(APPEND problems "  ${file}: ${line} (app/private is app's own)\n")
            endif()
        elseif(line MATCHES "[<\"]Framework/")
            string(APPEND problems "  ${file}: ${line} (compat/ is above every layer)\n")
        elseif(NO_SFML AND line MATCHES "[<\"]SFML/")
            string(APPEND problems "  ${file}: ${line} (this layer knows no SFML)\n")
        endif()
    endforeach()
    if(NOT foreign_types)
        continue()
    endif()
    file(STRINGS "${file}" declarations REGEX "^[ \t]*(class|struct)[ \t]+[A-Za-z_][A-Za-z0-9_]*[ \t]*;")
    foreach(line IN LISTS declarations)
        string(REGEX REPLACE "^[ \t]*(class|struct)[ \t]+([A-Za-z_][A-Za-z0-9_]*).*$" "\\2" name "${line}")
        if(name IN_LIST foreign_types)
            string(APPEND problems "  ${file}: ${line} (a type of ${defined_in_${name}}/)\n")
        endif()
    endforeach()
endforeach()
if(problems)
    string(REPLACE ";" ", " allowed_text "${ALLOWED}")
    if(NOT allowed_text)
        set(allowed_text "nothing below it")
    endif()
    message(FATAL_ERROR "Wrong-way include: framework/hitbox/${LAYER}/ may include (or forward-declare the types of) only "
                        "${LAYER}/ and ${allowed_text}.\n${problems}"
                        "See the layer table in framework/CMakeLists.txt.")
endif()
file(TOUCH "${STAMP}")
