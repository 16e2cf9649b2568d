# FindTetGen: Debian's libtet1.5-dev ships no CMake config.
# Defines TetGen_FOUND and the IMPORTED target TetGen::tetgen. The target carries TETLIBRARY, so
# that tetgen.h declares the library interface and terminatetetgen() throws an int instead of
# calling exit() (Debian's header leaves that define commented out).
include(${CMAKE_CURRENT_LIST_DIR}/meshprep_find_imported.cmake)
meshprep_find_imported(TetGen TetGen::tetgen tetgen.h NAMES tet tetgen DEFINES TETLIBRARY)
