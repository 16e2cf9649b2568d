# meshprep_set_warnings(target): -Wall -Wextra (and -Werror with MESHPREP_WERROR) on our own code only.
function(meshprep_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local)
  if(MESHPREP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# meshprep_add_module(NAME src...): the library meshprep_NAME with its alias meshprep::NAME, the
# module's include/ folder as its public interface, and our warnings. Dependencies are linked by
# the module's own CMakeLists.
function(meshprep_add_module name)
  add_library(meshprep_${name} ${ARGN})
  add_library(meshprep::${name} ALIAS meshprep_${name})
  target_include_directories(meshprep_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
  meshprep_set_warnings(meshprep_${name})
endfunction()
