# FindOpenBLAS: OpenBLAS (Debian: libopenblas-pthread-dev, or the serial build libopenblas-serial-dev;
# which one is found at run time, src/linalg/blas_kernels.hpp). Defines OpenBLAS_FOUND and
# the target OpenBLAS::OpenBLAS, which also makes Eigen call it for its dense products
# (EIGEN_USE_BLAS): OpenBLAS picks its kernels for the processor at run time, so a portable build
# gets AVX2/AVX-512 products that Eigen's own kernels only get with -march=native (measured on the
# coarse step's shapes, 202 × r by 202 × 201: 7–12 GFlop/s for Eigen without -march=native,
# 18–38 GFlop/s for OpenBLAS, docs/floor.md).
find_library(OpenBLAS_LIBRARY NAMES openblas)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenBLAS REQUIRED_VARS OpenBLAS_LIBRARY)
if(OpenBLAS_FOUND AND NOT TARGET OpenBLAS::OpenBLAS)
  add_library(OpenBLAS::OpenBLAS UNKNOWN IMPORTED)
  set_target_properties(OpenBLAS::OpenBLAS PROPERTIES IMPORTED_LOCATION "${OpenBLAS_LIBRARY}")
  if(NOT DEFINED STC_EIGEN_USE_BLAS OR STC_EIGEN_USE_BLAS)  # option of CMakeLists.txt, ON by default
    set_target_properties(OpenBLAS::OpenBLAS PROPERTIES INTERFACE_COMPILE_DEFINITIONS EIGEN_USE_BLAS)
  endif()
endif()
mark_as_advanced(OpenBLAS_LIBRARY)
