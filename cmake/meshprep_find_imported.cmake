# meshprep_find_imported(PACKAGE TARGET HEADER NAMES lib... [DEFINES def...]): the body of a find
# module for a Debian library that ships no CMake config. Finds HEADER and the library, sets
# PACKAGE_FOUND and defines the IMPORTED target TARGET with the compile definitions DEFINES.
# Installed beside the find modules that include it (cmake/meshprep_install.cmake).
macro(meshprep_find_imported package target header)
  cmake_parse_arguments(_meshprep_find "" "" "NAMES;DEFINES" ${ARGN})
  find_path(${package}_INCLUDE_DIR ${header})
  find_library(${package}_LIBRARY NAMES ${_meshprep_find_NAMES})
  include(FindPackageHandleStandardArgs)
  find_package_handle_standard_args(${package} REQUIRED_VARS ${package}_LIBRARY ${package}_INCLUDE_DIR)
  if(${package}_FOUND AND NOT TARGET ${target})
    add_library(${target} UNKNOWN IMPORTED)
    set_target_properties(${target} PROPERTIES
      IMPORTED_LOCATION "${${package}_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${${package}_INCLUDE_DIR}"
      INTERFACE_COMPILE_DEFINITIONS "${_meshprep_find_DEFINES}")
  endif()
  mark_as_advanced(${package}_INCLUDE_DIR ${package}_LIBRARY)
endmacro()
