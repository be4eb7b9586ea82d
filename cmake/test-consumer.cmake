# Installs this build into a scratch prefix, then configures, builds and runs
# examples/consumer against it, once with CMAKE_CXX_EXTENSIONS=OFF and once with ON.
# Arguments: SOURCE_DIR, BINARY_DIR, WORK_DIR, CXX.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BINARY_DIR}" --prefix "${prefix}" RESULT_VARIABLE rc)
if(rc)
    message(FATAL_ERROR "install failed")
endif()
foreach(ext OFF ON)
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
