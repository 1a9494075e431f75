#!/usr/bin/env bash
# check_pip_install.sh SOURCE_DIR BUILD_DIR PYTHON SCENE: `pip install .` as docs/python.md says,
# offline, into a fresh venv that PYTHON makes with --system-site-packages (NumPy from Debian),
# reusing BUILD_DIR's CMake build of the module (STC_CMAKE_BUILD_DIR, setup.py: only the module's
# target is brought up to date there). Then, from a folder outside the sources and the build, the
# venv's stcontact must be the installed one, with its stubs, version and licence, and solve SCENE.
set -euo pipefail
source=$1; build=$2; python=$3; scene=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" -m venv --system-site-packages "$work/venv"
# Only what is on this machine: no pip configuration, no other index or folder of wheels.
unset PIP_FIND_LINKS PIP_INDEX_URL PIP_EXTRA_INDEX_URL
export PIP_CONFIG_FILE=/dev/null PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_INPUT=1
STC_CMAKE_BUILD_DIR="$build" "$work/venv/bin/pip" install --no-build-isolation --no-index --no-cache-dir "$source"
cd "$work"
env -u PYTHONPATH PYTHONDONTWRITEBYTECODE=1 "$work/venv/bin/python" - "$scene" "$work/venv" <<'PY'
import importlib.metadata as metadata
import os
import sys

import stcontact

scene_file, venv = sys.argv[1:]
package = os.path.dirname(stcontact.__file__)
assert package.startswith(os.path.join(venv, "lib", "")), package
for name in ("__init__.py", "_results.py", "_scene_toml.py", "_core.pyi", "py.typed"):
    assert os.path.isfile(os.path.join(package, name)), name
assert metadata.version("stcontact") == stcontact.__version__, (metadata.version("stcontact"), stcontact.__version__)
assert metadata.metadata("stcontact")["License"] == "GPL-3.0-or-later"
assert any(file.name == "LICENSE" for file in metadata.files("stcontact"))  # the licence text, in dist-info
result = stcontact.solve(scene_file, "fas-apriori", sets=["mesh.arc_nodes=21", "time.steps=21"])
assert result.converged and result.error < 1e-5, result.summary["message"]
assert result.normal_forces.shape == (21, 21) and result.reactions["normal_force"][-1] > 0
print("pip installed stcontact", stcontact.__version__, "into", package, "->", result)
PY
