"""Results hold NumPy arrays of the documented shapes and layout, moved rather than copied; warm
starts, the per-iteration callback and the options behave as documented (docs/python.md)."""

import os

import numpy as np
import pytest

import stcontact


@pytest.fixture(scope="module")
def latin(small_scene):
    return stcontact.solve(small_scene, "latin", tol=1e-5)


def test_interface_arrays_have_the_documented_shapes(latin, small_scene):
    n_c, m = 31, 41
    assert latin.interface_forces.shape == latin.interface_displacements.shape == (2 * n_c, m)
    for array in (latin.normal_forces, latin.tangential_forces, latin.normal_displacements,
                  latin.tangential_displacements):
        assert array.shape == (n_c, m)
    assert latin.interface_forces.flags["F_CONTIGUOUS"]
    np.testing.assert_array_equal(latin.normal_forces, latin.interface_forces[0::2])
    np.testing.assert_array_equal(latin.tangential_forces[:, -1], latin.interface_forces[1::2, -1])
    assert np.shares_memory(latin.normal_forces, latin.interface_forces)  # a view, not a copy
    assert latin.times.shape == (m,) and latin.contact_nodes.shape == (n_c,)
    assert list(latin.contact_nodes) == list(small_scene.mesh()["contact_nodes"])


def test_large_arrays_are_moved_not_copied(latin):
    # The array does not own its data: the C++ matrix it was moved from lives in a capsule.
    assert not latin.interface_forces.flags["OWNDATA"]
    assert type(latin.interface_forces.base).__name__ == "PyCapsule"
    assert type(latin.history["indicator"].base).__name__ == "PyCapsule"


def test_reactions_and_history_columns(latin):
    m = 41
    assert set(latin.reactions) == {"step", "t", "normal_force", "tangential_force", "contact_xmin", "contact_xmax",
                                    "n_contact", "n_slip", "force_x", "force_y"}
    assert all(column.shape == (m,) for column in latin.reactions.values())
    # The reaction is the sum of the nodal contact forces.
    np.testing.assert_allclose(latin.reactions["normal_force"], latin.normal_forces.sum(axis=0), rtol=1e-12)
    assert latin.reactions["n_contact"][0] == 0 and np.isnan(latin.reactions["contact_xmin"][0])
    assert latin.reactions["n_contact"][-1] > 0
    assert {"iteration", "relaxations", "indicator", "error", "rank", "wall_s", "error_estimate",
            "sparse_solves", "krylov_iterations"} == set(latin.history)
    assert all(column.shape == (latin.iterations,) for column in latin.history.values())
    assert latin.history["indicator"][-1] <= 1e-5 and latin.converged
    assert latin.error == pytest.approx(latin.history["error"][-1], rel=1e-15)


def test_the_error_estimate_is_history_csvs_and_what_the_solve_stopped_on(latin):
    estimate = latin.history["error_estimate"]
    # +inf until the contraction rate is known: an empty cell in history.csv, NaN here.
    assert np.isnan(estimate[0]) and np.isfinite(estimate[-1])
    assert latin.summary["error_estimate"] == estimate[-1] and estimate[-1] <= 1e-5


def test_displacement_fields_are_rebuilt_on_request(latin, small_scene):
    sizes = small_scene.check()
    u = latin.displacement_fields()
    assert u.shape == (sizes["dofs"], 41)
    mesh = small_scene.mesh()
    top = np.isclose(mesh["nodes"][:, 1], 0.0)
    # The top edge is driven: u_y = -0.11 at the last instant (examples/scenes/hemicylinder.toml).
    np.testing.assert_allclose(u[1::2][top, -1], -0.11, rtol=1e-12)
    # The interface displacement is the normal component of the contact nodes' displacement.
    nodes = latin.contact_nodes
    normal_y = u[2 * nodes + 1, :]  # the obstacle's normal is (0, 1)
    np.testing.assert_allclose(latin.normal_displacements, normal_y, atol=1e-9)


def test_summary_is_summary_json(latin):
    assert latin.summary["solver"] == "latin"
    assert latin.summary["n_contact_nodes"] == 31 and latin.summary["n_steps"] == 41
    assert latin.summary["parameters"]["mesh"]["arc_nodes"] == 31
    assert latin.summary["iterations"] == latin.iterations == len(latin.history["iteration"])


def test_callback_sees_every_record_and_stops_the_solve(small_scene):
    records = []

    def stop_after_three(record):
        records.append(record)
        return record.iteration < 3

    result = stcontact.solve(small_scene, "latin", callback=stop_after_three)
    assert result.termination == "stopped_by_callback"
    assert result.iterations == 3 and [r.iteration for r in records] == [1, 2, 3]
    assert records[-1].error is not None and records[-1].indicator > 0
    assert result.summary["message"] == "stopped by the callback"


def test_records_carry_the_error_estimate_of_the_history(small_scene):
    records = []
    result = stcontact.solve(small_scene, "latin", tol=1e-12, max_iterations=30, callback=records.append)
    assert len(records) == result.iterations == 30
    # The records' estimate is the history's, None where the history has NaN (not yet known).
    for record, in_history in zip(records, result.history["error_estimate"]):
        assert (record.error_estimate is None) == bool(np.isnan(in_history))
        assert record.error_estimate is None or record.error_estimate == in_history
    assert records[0].error_estimate is None and "error_estimate=None" in repr(records[0])
    assert records[-1].error_estimate == result.summary["error_estimate"]


def test_callback_returning_none_goes_on(small_scene):
    result = stcontact.solve(small_scene, "latin", max_iterations=5, callback=lambda record: None)
    assert result.termination == "max_iterations" and result.iterations == 5


def test_an_exception_in_the_callback_stops_and_is_raised(small_scene):
    def fail(record):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        stcontact.solve(small_scene, "fas-apriori", callback=fail)


def test_warm_start_from_a_neighbour_takes_fewer_relaxations(small_scene):
    first = stcontact.solve(small_scene, "fas-apriori", sets={"contact.friction": 0.2}, reference=False)
    cold = stcontact.solve(small_scene, "fas-apriori", sets={"contact.friction": 0.25}, reference=False)
    warm = stcontact.solve(small_scene, "fas-apriori", sets={"contact.friction": 0.25}, reference=False,
                           start=first)
    assert cold.converged and warm.converged
    assert warm.summary["relaxations"] < cold.summary["relaxations"]
    # The same solution to the tolerance: the reactions agree to a small fraction of their largest value.
    largest = np.abs(cold.reactions["normal_force"]).max()
    np.testing.assert_allclose(warm.reactions["normal_force"], cold.reactions["normal_force"], atol=1e-5 * largest)
    assert first.spatial_modes.shape[0] == small_scene.check()["free_dofs"] and first.spatial_modes.shape[1] > 0
    assert first.interface_directions.shape[0] == 2 * small_scene.check()["contact_nodes"]
    assert first.interface_directions.shape[1] > 0
    # Orthonormal in the k⁻¹ product of the scene's search direction (docs/python.md).
    k = small_scene.mesh()["search_direction"]
    assert k.shape == (2 * small_scene.check()["contact_nodes"],) and np.all(k > 0.0)
    Z = first.interface_directions
    np.testing.assert_allclose(Z.T @ (Z / k[:, None]), np.eye(Z.shape[1]), rtol=0, atol=1e-10)


def test_spatial_modes_can_be_turned_off_without_changing_the_solution(small_scene):
    with_modes = stcontact.solve(small_scene, "fas-apriori", reference=False)
    without = stcontact.solve(small_scene, "fas-apriori", reference=False, spatial_modes=False)
    assert with_modes.spatial_modes.shape[1] > 0 and without.spatial_modes.shape[1] == 0
    # The modes are formed after the last iteration: the iterates are the same to the bit.
    np.testing.assert_array_equal(without.interface_forces, with_modes.interface_forces)
    assert without.summary["relaxations"] == with_modes.summary["relaxations"]
    assert without.summary["sparse_solves"] <= with_modes.summary["sparse_solves"]


def test_a_warm_start_of_other_sizes_is_refused(small_scene, latin):
    other = small_scene.with_sets("mesh.arc_nodes=21")
    with pytest.raises(ValueError, match="start history is 62"):
        stcontact.solve(other, "latin", start=latin)


def test_a_warm_start_with_nan_is_refused_naming_the_array(small_scene):
    # A result's arrays edited in place: NaN reached contact.csv and the true error read 0.0.
    for name in ["interface_forces", "interface_displacements", "interface_directions"]:
        start = stcontact.solve(small_scene, "latin-pgd", max_iterations=3, reference=False)
        getattr(start, name)[0, 0] = np.nan
        with pytest.raises(ValueError, match=r"start\.%s holds nan at row 0, column 0" % name):
            stcontact.solve(small_scene, "fas-apriori", start=start)


def test_a_callback_returning_nan_is_refused(small_scene):
    # NaN is true to Python: the solve went on as if the callback had said so.
    with pytest.raises(ValueError, match="callback returned nan"):
        stcontact.solve(small_scene, "latin", max_iterations=5, callback=lambda record: float("nan"))


def test_no_reference_means_no_true_error(small_scene):
    result = stcontact.solve(small_scene, "latin", max_iterations=3, reference=False)
    assert result.error is None and np.isnan(result.history["error"]).all()


def test_threads_change_no_result(small_scene):
    one = stcontact.solve(small_scene, "latin", max_iterations=20, reference=False, threads=1)
    two = stcontact.solve(small_scene, "latin", max_iterations=20, reference=False, threads=2)
    np.testing.assert_array_equal(one.interface_forces, two.interface_forces)
    assert one.summary["threads"] == 1 and two.summary["threads"] == 2


def test_out_writes_the_programs_files(small_scene, tmp_path):
    result = stcontact.solve(small_scene, "incremental", out=tmp_path)
    # the program's files, and the marker that lets the next run replace the folder (docs/interface.md)
    assert {p.name for p in tmp_path.iterdir()} == {"reactions.csv", "contact.csv", "history.csv", "summary.json",
                                                    "solution.h5", ".stcontact-run"}
    assert result.converged


def test_load_run_reads_back_what_the_solve_holds(small_scene, tmp_path):
    # The run folder read back (solution.h5 through h5py): the interface histories are the solve's own
    # arrays, pressure and shear are them over the tributary lengths, the reactions the solve's, and
    # every frame has the fields ParaView shows.
    scene = small_scene.with_sets({"output.frames": True, "output.frame_stride": 20, "output.field_precision": "float64"})
    result = stcontact.solve(scene, "fas-apriori", out=tmp_path, reference=False)
    with stcontact.load_run(tmp_path) as run:
        d, m = result.dimension, len(run.time)
        n_c = run.contact_nodes.shape[0]
        assert run.force.shape == (m, n_c, d) and m == 41
        for a in range(d):
            np.testing.assert_array_equal(run.force[:, :, a].T, result.interface_forces[a::d, :])
        np.testing.assert_array_equal(run.pressure, run.force[:, :, 0] / run.tributary)
        initial_gap = run.gap.T - result.interface_displacements[0::d, :]  # gap = g0 + v_n: g0 at every instant
        np.testing.assert_allclose(initial_gap, np.repeat(initial_gap[:, :1], m, axis=1), rtol=0, atol=1e-14)
        assert not run.slip[run.state == 0].any() and (run.state == 2).any()
        np.testing.assert_array_equal(run.reactions["normal_force"], result.reactions["normal_force"])
        assert list(run.frame_steps) == [0, 20, 40] and run.summary["solver"] == "fas-apriori"
        fields = run.frame(20)
        assert fields["displacement"].shape == (len(run.points), 3) and fields["stress"].shape == (len(run.cells), 6)
        with pytest.raises(KeyError, match="no frame"):
            run.frame(5)
        # the solve's result gives the frames' stress from u(lambda) (one factorisation); the frames come
        # from the held displacement, within tau = 1e-6 of it in energy (measured: 2e-8 of the largest)
        stress, von_mises = result.stress_fields()
        assert stress.shape == (m, len(run.cells), 6) and von_mises.shape == (m, len(run.cells))
        np.testing.assert_allclose(stress[20], fields["stress"], rtol=0, atol=1e-6 * np.abs(stress[20]).max())
        np.testing.assert_allclose(von_mises[20], fields["von_mises"], rtol=0, atol=1e-6 * np.abs(von_mises[20]).max())
        # the solve's result exposes the same contact columns, node by node (n_C x m)
        np.testing.assert_array_equal(result.pressure, run.pressure.T)
        np.testing.assert_array_equal(result.shear, run.shear[:, :, 0].T)
        np.testing.assert_array_equal(result.gap, run.gap.T)
        np.testing.assert_array_equal(result.slip, run.slip[:, :, 0].T)
        np.testing.assert_array_equal(result.state, run.state.T)


def test_every_strategy_solves(small_scene):
    assert set(stcontact.available_solvers()) == {"incremental", "latin", "latin-pgd", "fas-aposteriori",
                                                  "fas-apriori"}
    for solver in stcontact.available_solvers():
        result = stcontact.solve(small_scene, solver, tol=1e-4)
        assert result.converged, (solver, result.summary["message"])
        assert result.solver == solver and result.interface_forces.shape == (62, 41)


def test_blas_kernels_are_named_and_recorded(latin):
    # The import switched OpenBLAS off its generic fallback where the processor has AVX2 (docs/threads.md,
    # "BLAS kernels"), and summary.json records the kernels the solve ran on.
    assert stcontact.blas_kernels and latin.summary["blas_kernels"] == stcontact.blas_kernels
    with open("/proc/cpuinfo") as cpuinfo:
        flags = next((line.split(":", 1)[1].split() for line in cpuinfo if line.startswith("flags")), [])
    if "OPENBLAS_CORETYPE" not in os.environ and {"avx2", "fma"} <= set(flags):
        assert stcontact.blas_kernels != "Prescott"


def test_numpy_products_agree_after_the_kernel_switch():
    # NumPy shares the process's OpenBLAS when Debian's alternatives point both at it: its products
    # on the kernels the import switched to agree with a sum that calls no BLAS.
    a = np.random.default_rng(3).random((300, 200))
    b = np.random.default_rng(4).random((200, 100))
    np.testing.assert_allclose(a @ b, np.einsum("ij,jk->ik", a, b, optimize=False), rtol=1e-13, atol=0)
