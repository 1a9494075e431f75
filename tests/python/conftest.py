"""Shared fixtures of the Python module's tests (tests/python, run by ctest with the label python).

ctest sets PYTHONPATH to the build tree's python/ folder, STC_CLI to the built stcontact program and
STC_SOURCE_DIR to the repository, so that the module's answers are compared with the program's.
"""

import csv
import importlib.util
import json
import os
import subprocess
from pathlib import Path

import pytest

import stcontact

SOURCE_DIR = Path(os.environ.get("STC_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SEED_SCENE = SOURCE_DIR / "examples" / "scenes" / "hemicylinder.toml"
BAD_DIR = SOURCE_DIR / "tests" / "cli" / "bad"
# A small version of the seed scene for the tests that do not compare with the seed itself.
SMALL = ["mesh.arc_nodes=31", "time.steps=41", "output.frames=false"]


def load_script(file_name):
    """scripts/<file_name> as a module (the study scripts the docs quote, tested by their functions)."""
    spec = importlib.util.spec_from_file_location(Path(file_name).stem, SOURCE_DIR / "scripts" / file_name)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def cli():
    """The built stcontact program."""
    path = os.environ.get("STC_CLI")
    if not path or not os.access(path, os.X_OK):
        pytest.fail("STC_CLI must name the built stcontact program (ctest sets it)")
    return path


@pytest.fixture(scope="session")
def small_scene():
    return stcontact.load_scene(SEED_SCENE, sets=SMALL)


def run_cli(cli, *args, expect=0):
    """Runs the program; returns (stdout, stderr); fails the test on another exit status."""
    done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True, check=False)
    assert done.returncode == expect, "stcontact %s: exit %d\n%s" % (" ".join(map(str, args)), done.returncode,
                                                                     done.stderr)
    return done.stdout, done.stderr


def cli_error(cli, *args):
    """The program's one error line without its "error: " prefix (exit status 1)."""
    _, stderr = run_cli(cli, *args, expect=1)
    lines = stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), stderr
    return lines[0][len("error: "):]


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_json(path):
    with open(path) as f:
        return json.load(f)


def printed(value):
    """A number as the program's CSV writers print it (ostream precision 12, i.e. %.12g)."""
    return "%.12g" % value
