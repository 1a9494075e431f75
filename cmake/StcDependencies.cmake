# Finds every dependency as docs/architecture.md lists them; a missing one stops configuration with a
# message naming the Debian 12 package that provides it.
include(FindPackageHandleStandardArgs)

macro(stc_require found debian_package what)
  if(NOT ${found})
    message(FATAL_ERROR "stcontact needs ${what}: install the Debian package '${debian_package}' "
                        "(apt-get install -y ${debian_package})")
  endif()
endmacro()

find_package(Eigen3 3.4 QUIET NO_MODULE)
stc_require(Eigen3_FOUND libeigen3-dev "Eigen 3.4")

find_package(OpenBLAS QUIET)
stc_require(OpenBLAS_FOUND libopenblas-pthread-dev "OpenBLAS")

find_package(CHOLMOD QUIET)
stc_require(CHOLMOD_FOUND libsuitesparse-dev "SuiteSparse CHOLMOD")

find_package(ARPACK QUIET)
stc_require(ARPACK_FOUND libarpack2-dev "ARPACK")

find_package(GSL QUIET)
stc_require(GSL_FOUND libgsl-dev "GSL")

find_package(tomlplusplus QUIET)
stc_require(tomlplusplus_FOUND libtomlplusplus-dev "toml++")

find_package(nlohmann_json 3 QUIET)
stc_require(nlohmann_json_FOUND nlohmann-json3-dev "nlohmann-json")

find_package(CLI11 QUIET)
stc_require(CLI11_FOUND libcli11-dev "CLI11")

find_package(ZLIB QUIET)
stc_require(ZLIB_FOUND zlib1g-dev "zlib")

find_package(Threads REQUIRED)

if(STC_BUILD_TESTS)
  find_package(GTest QUIET)
  stc_require(GTest_FOUND libgtest-dev "GoogleTest")
endif()
if(STC_BUILD_BENCHMARKS)
  find_package(benchmark QUIET)
  stc_require(benchmark_FOUND libbenchmark-dev "Google Benchmark")
endif()

# Optional: the PETSc backends of the linear-solver seam (src/linalg/backends/petsc/: MUMPS's
# Cholesky, CG + GAMG), when PETSc (Debian: libpetsc-real-dev, which sets the /usr/lib/petsc link
# pkg-config reads) and an MPI (Open MPI) are found. Without them the build has the cholmod backend
# alone and says so; a scene asking for another backend is refused by name.
option(STC_WITH_PETSC "Build the PETSc backends (mumps, cg-gamg) when PETSc is found" ON)
set(STC_HAVE_PETSC OFF)
if(STC_WITH_PETSC)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(PETSC QUIET IMPORTED_TARGET PETSc)
  endif()
  find_package(MPI QUIET COMPONENTS CXX)  # mpi.h, through the C++ compiler
  if(PETSC_FOUND AND MPI_CXX_FOUND)
    set(STC_HAVE_PETSC ON)
    message(STATUS "PETSc ${PETSC_VERSION} with MPI ${MPI_CXX_VERSION}: linear backends cholmod, mumps, cg-gamg")
  else()
    message(STATUS "PETSc or MPI not found: linear backend cholmod only (libpetsc-real-dev adds mumps, cg-gamg)")
  endif()
endif()

# HDF5 writes solution.h5 (src/io/hdf5_file.cpp). One HDF5 in a process: with PETSc, the build
# PETSc links (Debian's links libhdf5_openmpi, from libhdf5-openmpi-dev, which it depends on); without
# it, the serial one (libhdf5-dev). Found through pkg-config; linked by path, as PETSc is.
find_package(PkgConfig QUIET)
stc_require(PkgConfig_FOUND pkg-config "pkg-config")
if(STC_HAVE_PETSC)
  pkg_check_modules(STC_HDF5 QUIET hdf5-openmpi)
  stc_require(STC_HDF5_FOUND libhdf5-openmpi-dev "HDF5 (the Open MPI build PETSc links)")
else()
  pkg_check_modules(STC_HDF5 QUIET hdf5-serial)
  if(NOT STC_HDF5_FOUND)
    pkg_check_modules(STC_HDF5 QUIET hdf5)
  endif()
  stc_require(STC_HDF5_FOUND libhdf5-dev "HDF5")
endif()
message(STATUS "HDF5 ${STC_HDF5_VERSION}: ${STC_HDF5_LINK_LIBRARIES}")
