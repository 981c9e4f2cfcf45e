# Warning flags for tide's own targets (never for third-party code).
function(tide_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion-null)
  if(TIDE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
