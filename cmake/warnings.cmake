# meshprep_set_warnings(target): -Wall -Wextra (and -Werror with MESHPREP_WERROR) on our own code only.
function(meshprep_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local)
  if(MESHPREP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
