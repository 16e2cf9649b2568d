# meshprep_set_warnings(target): -Wall -Wextra (and -Werror with MESHPREP_WERROR) on our own code only.
function(meshprep_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local>)
  if(MESHPREP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# meshprep_add_module(NAME src...): the library meshprep_NAME with its alias meshprep::NAME (also
# its exported name), the module's include/ folder as its public interface, and our warnings.
# Dependencies are linked by the module's own CMakeLists. The module registers itself in the
# global property MESHPREP_MODULES, which the umbrella target and the install rules iterate, so a
# new module needs no edit beyond its add_subdirectory.
function(meshprep_add_module name)
  add_library(meshprep_${name} ${ARGN})
  add_library(meshprep::${name} ALIAS meshprep_${name})
  set_target_properties(meshprep_${name} PROPERTIES EXPORT_NAME ${name})
  target_compile_features(meshprep_${name} PUBLIC cxx_std_17)  # the headers need C++17, so do consumers
  target_include_directories(meshprep_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
  meshprep_set_warnings(meshprep_${name})
  if(MESHPREP_SANITIZE)  # instrumented static libraries need the sanitizer runtimes wherever they are linked
    target_link_options(meshprep_${name} INTERFACE -fsanitize=address,undefined)
  endif()
  set_property(GLOBAL APPEND PROPERTY MESHPREP_MODULES meshprep_${name})
endfunction()

# meshprep_add_umbrella_target(): meshprep::meshprep, an INTERFACE library linking every module
# registered so far. Call it once every module is added.
function(meshprep_add_umbrella_target)
  get_property(modules GLOBAL PROPERTY MESHPREP_MODULES)
  add_library(meshprep_umbrella INTERFACE)
  add_library(meshprep::meshprep ALIAS meshprep_umbrella)
  set_target_properties(meshprep_umbrella PROPERTIES EXPORT_NAME meshprep)
  target_link_libraries(meshprep_umbrella INTERFACE ${modules})
endfunction()
