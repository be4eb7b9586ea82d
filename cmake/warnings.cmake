# Warnings for project targets, and the sanitizer switch.
function(incidence_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wconversion -Wshadow
        -Wno-sign-conversion)
    if(INCIDENCE_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()

function(incidence_sanitize target)
    if(INCIDENCE_SANITIZE)
        target_compile_options(${target} PUBLIC -fsanitize=address,undefined -fno-sanitize-recover=all
            -fno-omit-frame-pointer)
        target_link_options(${target} PUBLIC -fsanitize=address,undefined -fno-sanitize-recover=all)
    endif()
endfunction()
