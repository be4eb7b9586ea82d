# Warnings for project targets, and the sanitizer switch.
# BUILD_INTERFACE: CMake records a module library's own compile options in its installed package
# (the consumer rebuilds the modules with them); warnings and -Werror are our build's business, not
# our users', so the installed package leaves them out.
function(incidence_warnings target)
    target_compile_options(${target} PRIVATE $<BUILD_INTERFACE:-Wall -Wextra -Wpedantic -Wconversion -Wshadow
        -Wno-sign-conversion>)
    if(INCIDENCE_WERROR)
        target_compile_options(${target} PRIVATE $<BUILD_INTERFACE:-Werror>)
    endif()
endfunction()

function(incidence_sanitize target)
    if(INCIDENCE_SANITIZE)
        target_compile_options(${target} PUBLIC -fsanitize=address,undefined -fno-sanitize-recover=all
            -fno-omit-frame-pointer)
        target_link_options(${target} PUBLIC -fsanitize=address,undefined -fno-sanitize-recover=all)
    endif()
endfunction()

# Catch2 passes every CHECK's expression to __builtin_constant_p, and clang then tries to
# evaluate it in the compiler, up to the -fconstexpr-steps limit the library sets for its
# static_asserts (1e8). On the tests' constexpr fixtures that evaluates an exact query in the
# compiler, up to half a second per CHECK, and half of a test file's compile time. Sources of
# `target` without a static_assert get a small limit: a speculative evaluation that stops early
# changes nothing, and a required constant expression that needed more would be a compile error.
# (The option goes on the sources: a target's own options come before the library's.)
function(incidence_small_constexpr_limit target)
    get_target_property(sources ${target} SOURCES)
    foreach(src IN LISTS sources)
        # a batch of test files (tests/CMakeLists.txt) is read through its files
        get_source_file_property(files ${src} INCIDENCE_BATCH_FILES)
        if(NOT files)
            set(files ${src})
        endif()
        set(asserts "")
        foreach(file IN LISTS files)
            cmake_path(ABSOLUTE_PATH file BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} OUTPUT_VARIABLE path)
            file(STRINGS ${path} found REGEX "static_assert" LIMIT_COUNT 1)
            list(APPEND asserts ${found})
        endforeach()
        if(NOT asserts)
            set_property(SOURCE ${src} TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_OPTIONS -fconstexpr-steps=4096)
        endif()
    endforeach()
endfunction()
