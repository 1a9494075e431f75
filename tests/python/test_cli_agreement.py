"""The module's answers are the program's: the same solve of the seed scene gives the same
reactions.csv, history.csv and summary.json numbers (to the files' printing precision), and the
same sizes as `stcontact check`."""

import math
import re

import numpy as np
import pytest

import stcontact
from conftest import SEED_SCENE, SMALL, printed, read_csv, read_json, run_cli

NO_VTU = ["output.frames=false"]
# Keys of summary.json that measure the run rather than its result (at any depth: each
# preparation's "seconds").
TIMING_KEYS = {"wall_s", "seconds", "reference_s", "write_s", "run_s", "peak_memory_bytes", "peak_memory_bytes_per_rank"}


def untimed(value):
    """The value without its TIMING_KEYS, in lists and objects at any depth."""
    if isinstance(value, dict):
        return {k: untimed(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [untimed(v) for v in value]
    return value


@pytest.fixture(scope="module", params=["incremental", "fas-apriori"])
def solved(request, cli, tmp_path_factory):
    """The seed scene solved by the program and by the module with the same options."""
    out = tmp_path_factory.mktemp(request.param)
    run_cli(cli, "solve", SEED_SCENE, "--solver", request.param, "--set", NO_VTU[0], "--quiet", "--out", out)
    result = stcontact.solve(SEED_SCENE, request.param, sets=NO_VTU, spatial_modes=False)  # the program forms none
    return out, result


def test_reactions_equal_the_programs(solved):
    out, result = solved
    rows = read_csv(out / "reactions.csv")
    assert len(rows) == len(result.reactions["t"]) == 201
    for column in ["t", "normal_force", "tangential_force", "contact_xmin", "contact_xmax", "force_x", "force_y"]:
        module = ["" if math.isnan(v) else printed(v) for v in result.reactions[column]]
        assert module == [row[column] for row in rows], column
    for column in ["step", "n_contact", "n_slip"]:
        assert [str(v) for v in result.reactions[column]] == [row[column] for row in rows], column


def test_history_equals_the_programs(solved):
    out, result = solved
    rows = read_csv(out / "history.csv")
    assert len(rows) == len(result.history["iteration"]) == result.iterations
    for column in ["iteration", "relaxations", "rank", "sparse_solves"]:
        assert [str(v) for v in result.history[column]] == [row[column] for row in rows], column
    for column in ["indicator", "error", "error_estimate"]:  # NaN where the file's cell is empty
        module = ["" if math.isnan(v) else printed(v) for v in result.history[column]]
        assert module == [row[column] for row in rows], column


def test_summary_equals_the_programs(solved):
    out, result = solved
    program = read_json(out / "summary.json")
    assert list(result.summary) == list(program)  # the same keys, in the same order
    for key in program:
        if key not in TIMING_KEYS:
            assert untimed(result.summary[key]) == untimed(program[key]), key
    assert result.converged and result.summary["termination"] == "converged"


def test_contact_forces_equal_the_programs(solved):
    out, result = solved
    rows = read_csv(out / "contact.csv")
    n_c, m = result.normal_forces.shape
    assert len(rows) == n_c * m
    normal = np.array([float(row["normal_force"]) for row in rows]).reshape(m, n_c).T
    np.testing.assert_allclose(result.normal_forces, normal, rtol=1e-10, atol=1e-12 * np.abs(normal).max())
    nodes = [int(row["node"]) for row in rows[:n_c]]
    assert nodes == list(result.contact_node_tags)
    assert list(result.contact_node_tags) == list(result.contact_nodes + 1)  # a generated mesh: from 1


def test_check_equals_the_programs(cli):
    stdout, _ = run_cli(cli, "check", SEED_SCENE, *[arg for s in SMALL for arg in ("--set", s)])
    sizes = stcontact.check(SEED_SCENE, sets=SMALL)

    def field(pattern):
        match = re.search(pattern, stdout, re.MULTILINE)
        assert match, pattern
        return match.groups()

    assert field(r"^nodes\s+(\d+)$") == (str(sizes["nodes"]),)
    assert field(r"^elements\s+(\d+)$") == (str(sizes["elements"]),)
    assert field(r"^dofs\s+(\d+) \((\d+) free, (\d+) prescribed\)$") == (
        str(sizes["dofs"]), str(sizes["free_dofs"]), str(sizes["prescribed_dofs"]))
    assert field(r"^contact nodes\s+(\d+) on boundary '(\w+)' \((\d+) interface unknowns") == (
        str(sizes["contact_nodes"]), sizes["boundary"], str(sizes["interface_rows"]))
    assert field(r"^steps\s+(\d+) instants") == (str(sizes["instants"]),)
    assert field(r"kappa = (\S+), L") == ("%g" % sizes["kappa"],)
    assert sizes["contact_nodes"] == 31 and sizes["instants"] == 41
