#!/usr/bin/env bash
# Installs every build, test and plotting dependency from Debian 12's archive (run as root).
# OpenBLAS (its pthread build, with its headers and link library) serves Eigen's dense products
# (cmake/FindOpenBLAS.cmake: EIGEN_USE_BLAS) and replaces the reference BLAS behind CHOLMOD and
# ARPACK; the pthread build takes calls from two threads at once (the serial one returns wrong
# results then), so long products and 3D solves run on stcontact's threads (docs/threads.md).
# clang-14 + libclang-rt-14-dev (libFuzzer, clang's sanitizer runtimes) build the fuzz targets
# (scripts/fuzz.sh); llvm-14's llvm-symbolizer puts file:line into sanitizer reports.
# pybind11, the Python headers, NumPy, pytest and matplotlib: the Python module, its tests and
# examples (docs/python.md), for Debian's /usr/bin/python3; venv (with the pip and setuptools wheels
# it bundles), setuptools and wheel: `pip install .` offline (test python.pip_install). zlib
# compresses the .vtu frames; python3-meshio reads them back in the tests, as a reader that shares
# no code with the writer. python3-gmsh: the mesh scripts of examples/meshes/ (docs/meshing.md).
# PETSc (with MUMPS, GAMG, hypre) and Open MPI: the linear backends mumps and cg-gamg
# (docs/linear_solvers.md); a build without them has the cholmod backend alone.
# HDF5 writes solution.h5 (libhdf5-dev; with PETSc, the Open MPI build PETSc links, which its package
# brings); python3-h5py reads it back in the tests and in stcontact.load_run.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends \
  g++ cmake make pkg-config \
  libeigen3-dev libsuitesparse-dev libarpack2-dev libgsl-dev libopenblas-pthread-dev \
  libtomlplusplus-dev nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev zlib1g-dev \
  gnuplot-nox clang-14 libclang-rt-14-dev llvm-14 \
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib python3-meshio \
  python3-venv python3-setuptools python3-wheel python3-gmsh \
  libhdf5-dev python3-h5py libpetsc-real3.18-dev openmpi-bin >/dev/null
echo "dependencies installed"
