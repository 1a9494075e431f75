# The Python module (python/, docs/python.md): option STC_BUILD_PYTHON, on by default when
# pybind11, Python 3 with its development files and NumPy are found (Debian 12: pybind11-dev,
# python3-dev, python3-numpy), off otherwise with a message. Included before the targets.
#
# The interpreter: Debian's /usr/bin/python3 when it exists, the one the Debian packages above
# belong to, so that an interpreter that comes first on PATH (pyenv, conda) and lacks them is not
# picked; -DPython3_EXECUTABLE=... chooses another.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter of the stcontact module")
endif()
set(Python3_FIND_STRATEGY LOCATION)
set(Python3_FIND_VIRTUALENV STANDARD)

# Python first: pybind11 then uses FindPython3's targets (its "new" mode).
find_package(Python3 3.8 QUIET COMPONENTS Interpreter OPTIONAL_COMPONENTS Development.Module NumPy)
find_package(pybind11 2.6 QUIET CONFIG)

set(stc_python_missing "")
if(NOT pybind11_FOUND)
  list(APPEND stc_python_missing pybind11-dev)
endif()
if(NOT Python3_Development.Module_FOUND)
  list(APPEND stc_python_missing python3-dev)
endif()
if(NOT Python3_NumPy_FOUND)
  list(APPEND stc_python_missing python3-numpy)
endif()
if(stc_python_missing OR STC_BUILD_FUZZERS)  # an instrumented extension cannot load into a plain interpreter
  set(stc_python_default OFF)
else()
  set(stc_python_default ON)
endif()
option(STC_BUILD_PYTHON "Build the stcontact Python module (pybind11, NumPy)" ${stc_python_default})

if(STC_BUILD_PYTHON AND stc_python_missing)
  list(JOIN stc_python_missing " " stc_packages)
  message(FATAL_ERROR "STC_BUILD_PYTHON=ON needs ${stc_packages} for ${Python3_EXECUTABLE}: install the Debian "
                      "packages (apt-get install -y ${stc_packages}), or configure with -DSTC_BUILD_PYTHON=OFF")
elseif(STC_BUILD_PYTHON)
  message(STATUS "Python module: on (Python ${Python3_VERSION} at ${Python3_EXECUTABLE}, pybind11 ${pybind11_VERSION})")
elseif(stc_python_missing)
  list(JOIN stc_python_missing " " stc_packages)
  message(STATUS "Python module: off (not found: ${stc_packages}; apt-get install -y ${stc_packages})")
else()
  message(STATUS "Python module: off (STC_BUILD_PYTHON=OFF)")
endif()

# Where `cmake --install` puts the package, below the prefix: the site folder Debian's interpreter
# searches for this prefix (/usr and /usr/local: lib/python3.X/dist-packages).
set(STC_PYTHON_INSTALL_DIR "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages"
    CACHE STRING "Install folder of the stcontact Python package, relative to the prefix")
