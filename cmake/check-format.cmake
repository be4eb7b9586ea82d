# The C++ sources are formatted as .clang-format says: clang-format --dry-run --Werror on every
# .cppm, .cpp and .hpp file of the tree (a file added since configuring is included). Run by the
# format_check test: cmake -DCLANG_FORMAT=<clang-format-19> -DSOURCE_DIR=<tree> -P check-format.cmake
if(NOT CLANG_FORMAT)
    message(FATAL_ERROR "clang-format-19 was not found: ./run.sh test installs it (package clang-format-19)")
endif()
set(files "")
foreach(dir modules tests testkit fuzz bench tools examples cmake)
    file(GLOB_RECURSE found ${SOURCE_DIR}/${dir}/*.cppm ${SOURCE_DIR}/${dir}/*.cpp ${SOURCE_DIR}/${dir}/*.hpp)
    list(APPEND files ${found})
endforeach()
list(LENGTH files count)
execute_process(COMMAND ${CLANG_FORMAT} --style=file --dry-run --Werror ${files}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE rc ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
    string(REGEX MATCHALL "[^\n]*: error: code should be clang-formatted[^\n]*" bad "${out}")
    list(LENGTH bad nbad)
    string(REPLACE ";" "\n" bad "${bad}")
    message(FATAL_ERROR "${nbad} places are not formatted (clang-format-19 -i <file> formats one):\n${bad}")
endif()
message(STATUS "[cases] format_check: ${count} files formatted as .clang-format says")
