# Run as a script (cmake -P) by the build: fails when a file of one layer includes a layer it
# may not use. Called by hitbox_layer() in framework/CMakeLists.txt with:
#   LAYER    the layer's name (geometry, broadphase, ...)
#   ALLOWED  ";"-separated layers this one may include (its own is always allowed)
#   NO_SFML  ON when the layer must not include SFML at all
#   FILES    ";"-separated files to read
#   STAMP    the file to touch when every include is allowed
cmake_minimum_required(VERSION 3.16)
set(problems "")
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
endforeach()
if(problems)
    string(REPLACE ";" ", " allowed_text "${ALLOWED}")
    if(NOT allowed_text)
        set(allowed_text "nothing below it")
    endif()
    message(FATAL_ERROR "Wrong-way include: framework/hitbox/${LAYER}/ may include only "
                        "${LAYER}/ and ${allowed_text}.\n${problems}"
                        "See the layer table in framework/CMakeLists.txt.")
endif()
file(TOUCH "${STAMP}")
