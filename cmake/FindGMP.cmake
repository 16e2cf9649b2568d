# FindGMP: Debian's libgmp-dev ships no CMake config.
# Defines GMP_FOUND and the IMPORTED targets GMP::gmp (the C library: the exact stage of quality/'s
# orientation predicates) and GMP::gmpxx (its C++ interface, mpq_class: the repair's exact cuts).
include(${CMAKE_CURRENT_LIST_DIR}/meshprep_find_imported.cmake)
meshprep_find_imported(GMP GMP::gmp gmp.h NAMES gmp)
# libgmp-dev ships gmpxx beside gmp: without it GMP counts as not found.
find_library(GMP_CXX_LIBRARY NAMES gmpxx)
mark_as_advanced(GMP_CXX_LIBRARY)
if(NOT GMP_CXX_LIBRARY)
  set(GMP_FOUND FALSE)
elseif(GMP_FOUND AND NOT TARGET GMP::gmpxx)
  add_library(GMP::gmpxx UNKNOWN IMPORTED)
  set_target_properties(GMP::gmpxx PROPERTIES IMPORTED_LOCATION "${GMP_CXX_LIBRARY}" INTERFACE_LINK_LIBRARIES GMP::gmp)
endif()
