# FindARPACK: ARPACK-NG, called directly through its Fortran reverse-communication routines
# (dsaupd_/dseupd_). Debian: libarpack2-dev. Defines ARPACK_FOUND and the target ARPACK::ARPACK.
find_library(ARPACK_LIBRARY arpack)
find_package(LAPACK QUIET)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ARPACK REQUIRED_VARS ARPACK_LIBRARY)
if(ARPACK_FOUND AND NOT TARGET ARPACK::ARPACK)
  add_library(ARPACK::ARPACK UNKNOWN IMPORTED)
  set_target_properties(ARPACK::ARPACK PROPERTIES IMPORTED_LOCATION "${ARPACK_LIBRARY}")
  if(LAPACK_FOUND)
    set_target_properties(ARPACK::ARPACK PROPERTIES INTERFACE_LINK_LIBRARIES "${LAPACK_LIBRARIES}")
  endif()
endif()
mark_as_advanced(ARPACK_LIBRARY)
