# FindTetGen: Debian's libtet1.5-dev ships no CMake config.
# Defines TetGen_FOUND and the IMPORTED target TetGen::tetgen. The target carries TETLIBRARY, so
# that tetgen.h declares the library interface and terminatetetgen() throws an int instead of
# calling exit() (Debian's header leaves that define commented out).
find_path(TetGen_INCLUDE_DIR tetgen.h)
find_library(TetGen_LIBRARY NAMES tet tetgen)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(TetGen REQUIRED_VARS TetGen_LIBRARY TetGen_INCLUDE_DIR)
if(TetGen_FOUND AND NOT TARGET TetGen::tetgen)
  add_library(TetGen::tetgen UNKNOWN IMPORTED)
  set_target_properties(TetGen::tetgen PROPERTIES
    IMPORTED_LOCATION "${TetGen_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${TetGen_INCLUDE_DIR}"
    INTERFACE_COMPILE_DEFINITIONS TETLIBRARY)
endif()
mark_as_advanced(TetGen_INCLUDE_DIR TetGen_LIBRARY)
