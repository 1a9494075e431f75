#!/usr/bin/env bash
# check_install.sh BUILD_DIR PYTHON SITE_DIR SCENE: installs BUILD_DIR into a temporary prefix and
# imports stcontact from PREFIX/SITE_DIR with PYTHON, from a folder outside the build and the
# sources; the installed module must check and solve SCENE (small settings).
set -euo pipefail
build=$1; python=$2; site=$3; scene=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cd "$work"
PYTHONPATH="$work/prefix/$site" PYTHONDONTWRITEBYTECODE=1 "$python" - "$scene" "$work/prefix/$site" <<'PY'
import os, sys
import stcontact
scene_file, site = sys.argv[1:]
assert os.path.dirname(stcontact.__file__) == os.path.join(site, "stcontact"), stcontact.__file__
for name in ("_core.pyi", "py.typed"):  # the type stubs and the typed-package marker (PEP 561)
    assert os.path.isfile(os.path.join(site, "stcontact", name)), name
result = stcontact.solve(scene_file, "fas-apriori", sets=["mesh.arc_nodes=21", "time.steps=21"])
assert result.converged, result.summary["message"]
print("stcontact", stcontact.__version__, "from", os.path.dirname(stcontact.__file__), "->", result)
PY
