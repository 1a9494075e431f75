"""`pip install .` (docs/python.md, "Installing with pip"): a wheel of the package stcontact, with the
files of python/stcontact/ (pure Python, type stubs, py.typed) and the extension stcontact._core,
which build_ext builds with the project's own CMake (the target stcontact_python of
python/CMakeLists.txt) for the interpreter that runs pip. The metadata is in pyproject.toml; the
version is the project VERSION of CMakeLists.txt.

The CMake build folder, where setuptools also keeps its own files, is build-pip/ beside this file
(kept between installs, so that a second install recompiles only what changed), or the folder named
by STC_CMAKE_BUILD_DIR: an existing build configured with STC_BUILD_PYTHON=ON for the same Python
version (scripts/build.sh's build/), where only the module's target is brought up to date.
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
REUSED_BUILD = os.environ.get("STC_CMAKE_BUILD_DIR")
BUILD = Path(REUSED_BUILD).resolve() if REUSED_BUILD else ROOT / "build-pip"


def project_version():
    """The project VERSION of CMakeLists.txt, the one source of the version."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*stcontact\s+VERSION\s+([0-9]+(?:\.[0-9]+)*)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no 'project(stcontact VERSION x.y.z' line")
    return match.group(1)


def run(command):
    print(" ".join(map(str, command)), flush=True)
    subprocess.run([str(part) for part in command], check=True)


def configure():
    """Configures BUILD for this interpreter: the libraries and the module, neither tests nor programs."""
    run(["cmake", "-S", ROOT, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release", "-DSTC_BUILD_TESTS=OFF",
         "-DSTC_BUILD_PYTHON=ON", "-DPython3_EXECUTABLE=" + sys.executable])


def require_python_module_build():
    """A reused build must have the module on (it is built for the interpreter it was configured with)."""
    cache = BUILD / "CMakeCache.txt"
    if not cache.is_file():
        raise RuntimeError("STC_CMAKE_BUILD_DIR=%s is not a configured CMake build folder" % BUILD)
    if not re.search(r"^STC_BUILD_PYTHON:BOOL=ON$", cache.read_text(), re.MULTILINE):
        raise RuntimeError("STC_CMAKE_BUILD_DIR=%s was configured with STC_BUILD_PYTHON=OFF" % BUILD)


class CMakeBuild(build_ext):
    """Builds stcontact._core with CMake and copies it where setuptools puts the package."""

    def build_extension(self, ext):
        if REUSED_BUILD:
            require_python_module_build()
        else:
            configure()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        run(["cmake", "--build", BUILD, "--target", "stcontact_python", "--parallel", jobs])
        # The name carries the interpreter's ABI tag: a module built for another Python is not found.
        built = BUILD / "python" / "stcontact" / ("_core" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.is_file():
            raise RuntimeError("%s was not built: is %s configured for this Python (%s)?" % (built, BUILD, sys.executable))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(
    version=project_version(),
    packages=["stcontact"],
    package_dir={"": "python"},
    package_data={"stcontact": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("stcontact._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own files beside the CMake build, not in the sources.
    options={"build": {"build_base": str(BUILD / "setuptools")}, "egg_info": {"egg_base": str(BUILD)}},
    zip_safe=False,
)
