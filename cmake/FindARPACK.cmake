# FindARPACK: ARPACK-NG, called through its typed C++ interface (arpack/arpack.hpp: arpack::saupd,
# arpack::seupd over the ISO C binding). Debian: libarpack2-dev. Defines ARPACK_FOUND and the target
# ARPACK::ARPACK.
find_library(ARPACK_LIBRARY arpack)
find_path(ARPACK_INCLUDE_DIR arpack/arpack.hpp)
find_package(LAPACK QUIET)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ARPACK REQUIRED_VARS ARPACK_LIBRARY ARPACK_INCLUDE_DIR)
if(ARPACK_FOUND AND NOT TARGET ARPACK::ARPACK)
  add_library(ARPACK::ARPACK UNKNOWN IMPORTED)
  set_target_properties(ARPACK::ARPACK PROPERTIES IMPORTED_LOCATION "${ARPACK_LIBRARY}"
                                                  INTERFACE_INCLUDE_DIRECTORIES "${ARPACK_INCLUDE_DIR}")
  if(LAPACK_FOUND)
    set_target_properties(ARPACK::ARPACK PROPERTIES INTERFACE_LINK_LIBRARIES "${LAPACK_LIBRARIES}")
  endif()
endif()
mark_as_advanced(ARPACK_LIBRARY ARPACK_INCLUDE_DIR)
