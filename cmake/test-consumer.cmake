# Installs this build into a scratch prefix, then configures, builds and runs
# examples/consumer against it with CMAKE_CXX_EXTENSIONS=OFF. That is the setting that tells: the
# library is built with clang's default (ON, -std=gnu++20), and clang refuses a module built with
# one -std in a translation unit of the other, so the consumer builds only if the installed config
# follows its setting (incidence-config.cmake). ON, the default, would build even if it did not; a
# second build with it took 75 of this test's 151 s.
# Arguments: SOURCE_DIR, BINARY_DIR, WORK_DIR, CXX.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BINARY_DIR}" --prefix "${prefix}" RESULT_VARIABLE rc)
if(rc)
    message(FATAL_ERROR "install failed")
endif()
# The installed package passes on only what correctness needs (-ffp-contract=off, the constexpr
# step limit): never our warnings or -Werror, which would fail a user's build on a new warning.
file(GLOB_RECURSE exported "${prefix}/*.cmake")
foreach(f IN LISTS exported)
    file(READ "${f}" text)
    foreach(flag -Werror -Wall -Wextra -Wpedantic -Wconversion -Wshadow)
        string(FIND "${text}" "${flag}" at)
        if(NOT at EQUAL -1)
            message(FATAL_ERROR "the installed ${f} exports ${flag}")
        endif()
    endforeach()
endforeach()
foreach(ext OFF)
    set(build "${WORK_DIR}/build-ext-${ext}")
    execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples/consumer" -B "${build}" -G Ninja
        -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_EXTENSIONS=${ext}
        -DCMAKE_BUILD_TYPE= RESULT_VARIABLE rc) # unoptimised: the point is that the installed modules build and link
    if(rc)
        message(FATAL_ERROR "consumer configure failed (CMAKE_CXX_EXTENSIONS=${ext})")
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} --build "${build}" RESULT_VARIABLE rc)
    if(rc)
        message(FATAL_ERROR "consumer build failed (CMAKE_CXX_EXTENSIONS=${ext})")
    endif()
    execute_process(COMMAND "${build}/app" RESULT_VARIABLE rc)
    if(rc)
        message(FATAL_ERROR "consumer run failed (CMAKE_CXX_EXTENSIONS=${ext})")
    endif()
    message(STATUS "consumer OK with CMAKE_CXX_EXTENSIONS=${ext}")
endforeach()
