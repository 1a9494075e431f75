"""svd, true_error and compare: the program's numbers from the module, in the documented shapes."""

import numpy as np
import pytest

import stcontact
from conftest import SEED_SCENE, SMALL, cli_error, read_csv, run_cli

SMALL_ARGS = [arg for s in SMALL for arg in ("--set", s)]


def test_svd_equals_the_programs(cli, small_scene, tmp_path):
    run_cli(cli, "svd", SEED_SCENE, *SMALL_ARGS, "--modes", 6, "--out", tmp_path)
    result = stcontact.svd(small_scene, modes=6)
    rows = read_csv(tmp_path / "singular_values.csv")
    assert len(rows) == len(result.sigma) == 40  # m - 1 pairs: fewer than the 50 the program wants
    # ARPACK starts from a random vector: the leading values agree to its tolerance, not to the digit.
    program_sigma = np.array([float(row["sigma"]) for row in rows])
    np.testing.assert_allclose(result.sigma[:10], program_sigma[:10], rtol=1e-9)
    np.testing.assert_allclose(result.cumulative_energy[:10], [float(r["cumulative_energy"]) for r in rows[:10]],
                               rtol=1e-9)
    time_functions = read_csv(tmp_path / "time_functions.csv")
    assert result.time_functions.shape == (41, 6)
    program = np.array([[float(row["mode_%d" % (i + 1)]) for i in range(6)] for row in time_functions])
    np.testing.assert_allclose(result.time_functions[:, :3], program[:, :3], atol=1e-7 * np.abs(program).max())
    sizes = small_scene.check()
    assert result.spatial_modes.shape == (sizes["dofs"], 6)
    assert result.modes_for_energy["99.9%"] is not None and result.modes_for_energy["99.9%"] <= 40


def test_svd_refuses_what_the_program_refuses(cli, small_scene, tmp_path):
    expected = cli_error(cli, "svd", SEED_SCENE, *SMALL_ARGS, "--modes", 41, "--out", tmp_path)
    with pytest.raises(ValueError) as raised:
        stcontact.svd(small_scene, modes=41)
    assert str(raised.value) == expected and expected.startswith("--modes = 41 must be in [1, 40]")


def test_true_error_is_the_runs_own_and_the_programs(cli, small_scene, tmp_path):
    """A solve that measured its true error wrote it into solution.h5: measured again from the file, by
    the module and by the program, it is the same (the same reference, the forces read back bit for bit)."""
    result = stcontact.solve(small_scene, "fas-apriori", out=tmp_path / "run", spatial_modes=False)
    own = result.summary["error"]
    check = stcontact.true_error(small_scene, tmp_path / "run" / "solution.h5")
    assert 0 < own <= 1e-6 and abs(check["error"] - own) <= 1e-9 * own and check["run_error"] == own
    assert check["solver"] == "fas-apriori" and check["error_estimate"] == result.summary["error_estimate"]
    stdout, _ = run_cli(cli, "true-error", SEED_SCENE, *SMALL_ARGS, "--solution", tmp_path / "run" / "solution.h5",
                        "--quiet")
    assert stdout.startswith("true error %.6e " % check["error"])


def test_true_error_refuses_another_model(cli, small_scene, tmp_path):
    stcontact.solve(small_scene, "incremental", out=tmp_path / "run")
    other = small_scene.with_sets({"contact.friction": 0.3})
    expected = cli_error(cli, "true-error", SEED_SCENE, *SMALL_ARGS, "--set", "contact.friction=0.3", "--solution",
                         tmp_path / "run" / "solution.h5")
    with pytest.raises(stcontact.InputError) as raised:
        stcontact.true_error(other, tmp_path / "run" / "solution.h5")
    assert str(raised.value) == expected and "the model differs" in expected


@pytest.fixture(scope="module")
def comparison(tmp_path_factory):
    out = tmp_path_factory.mktemp("compare")
    result = stcontact.compare(SEED_SCENE, ["incremental", "latin", "fas-apriori"], repeats=1, tol=1e-6, sets=SMALL,
                               out=out)
    return out, result


def test_compare_returns_every_strategy_and_the_table(comparison):
    out, result = comparison
    assert list(result.strategies) == ["incremental", "latin", "fas-apriori"]
    assert [row["solver"] for row in result.summary] == ["incremental", "latin", "fas-apriori"]
    for name, strategy in result.strategies.items():
        assert strategy.termination == "converged" and len(strategy.runs) == 1
        points = strategy.runs[0]["points"]
        assert set(points) == {"iteration", "relaxations", "sparse_solves", "indicator", "error", "wall_s"}
        assert len({len(column) for column in points.values()}) == 1
    latin = result.strategies["latin"].runs[0]["points"]
    assert latin["error"][-1] < latin["error"][0] and np.all(np.diff(latin["wall_s"]) >= 0)
    assert result.summary[1]["repeats_reaching_1e-4"] == 1 and result.summary[1]["time_to_1e-4_s"] > 0


def test_compare_table_is_the_report_written(comparison):
    out, result = comparison
    assert (out / "summary.csv").read_text() == result.summary_csv
    assert (out / "work_precision.csv").read_text() == result.work_precision_csv
    assert (out / "summary.md").read_text() == result.summary_markdown
    assert len(read_csv(out / "summary.csv")) == len(result.summary)


def test_compare_iterations_equal_the_programs(cli, comparison, tmp_path):
    _, result = comparison
    run_cli(cli, "compare", SEED_SCENE, "--solvers", "latin,fas-apriori", "--repeats", 1, "--tol", "1e-6",
            *SMALL_ARGS, "--quiet", "--out", tmp_path)
    for row in read_csv(tmp_path / "summary.csv"):
        strategy = result.strategies[row["solver"]]
        assert row["termination"] == strategy.termination
        assert int(row["iterations"]) == strategy.iterations
        assert row["final_error"] == "%.4g" % strategy.final_error
