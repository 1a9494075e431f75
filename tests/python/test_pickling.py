"""Scenes and results pickle: the copy equals the original and serves in further calls (a scene is
solved, a result warm-starts a solve and rebuilds its displacement fields)."""

import pickle
import tomllib

import numpy as np

import stcontact
from conftest import SEED_SCENE, SMALL


def round_trip(value):
    return pickle.loads(pickle.dumps(value))


def assert_same_arrays(a, b):
    assert set(a) == set(b)
    for key in a:
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)  # NaN equal to NaN


def test_a_scene_from_a_file_round_trips_and_solves(small_scene):
    copy = round_trip(small_scene)
    assert copy == small_scene and hash(copy) == hash(small_scene)
    assert (copy.text, copy.source, copy.sets, copy.parameters) == (small_scene.text, small_scene.source,
                                                                   small_scene.sets, small_scene.parameters)
    assert copy.check() == small_scene.check()
    assert stcontact.solve(copy, "latin", max_iterations=3, reference=False).iterations == 3


def test_a_scene_from_a_dict_round_trips():
    with open(SEED_SCENE, "rb") as f:
        scene = stcontact.Scene.from_dict(tomllib.load(f), sets=SMALL)
    copy = round_trip(scene)
    assert copy == scene and copy.source == "<dict>" and copy.sets == SMALL
    assert copy != scene.with_sets("contact.friction=0.3")


def test_a_solve_result_round_trips_and_serves_further_calls(small_scene):
    result = stcontact.solve(small_scene, "fas-apriori", tol=1e-6)
    copy = round_trip(result)
    assert copy.summary == result.summary and copy.solver == result.solver
    assert_same_arrays(copy.history, result.history)
    assert_same_arrays(copy.reactions, result.reactions)
    for name in ("interface_forces", "interface_displacements", "spatial_modes", "interface_directions", "times",
                 "contact_nodes"):
        np.testing.assert_array_equal(getattr(copy, name), getattr(result, name), err_msg=name)
    # The problem is assembled again from the pickled scene: the same displacement fields.
    np.testing.assert_array_equal(copy.displacement_fields(), result.displacement_fields())
    assert copy.problem.n_dofs == result.problem.n_dofs
    warm = stcontact.solve(small_scene, "fas-apriori", tol=1e-6, start=copy)
    assert warm.converged and warm.summary["relaxations"] < result.summary["relaxations"]


def test_iteration_records_round_trip(small_scene):
    records = []
    stcontact.solve(small_scene, "latin", max_iterations=4, callback=records.append)
    copies = round_trip(records)
    assert [repr(r) for r in copies] == [repr(r) for r in records]
    assert [(r.sparse_solves, r.krylov_iterations, r.error, r.error_estimate) for r in copies] == [
        (r.sparse_solves, r.krylov_iterations, r.error, r.error_estimate) for r in records]


def test_an_svd_result_round_trips(small_scene):
    result = stcontact.svd(small_scene, modes=3)
    copy = round_trip(result)
    np.testing.assert_array_equal(copy.sigma, result.sigma)
    np.testing.assert_array_equal(copy.spatial_modes, result.spatial_modes)
    assert copy.modes_for_energy == result.modes_for_energy and repr(copy) == repr(result)
