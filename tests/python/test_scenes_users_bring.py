"""Two bodies, a moving obstacle and a rigid profile through the module: the pairs in the results and
the mesh, displacement fields in the scene's frame when the obstacle moves, a polyline scene solved."""

import numpy as np

import stcontact
from conftest import SOURCE_DIR

SCENES = SOURCE_DIR / "examples" / "scenes"
SMALL = ["mesh.arc_nodes=21", "time.steps=21", "output.frames=false"]


def test_two_bodies_give_each_contact_node_its_master():
    scene = stcontact.load_scene(SCENES / "two_cylinders.toml", sets=SMALL)
    mesh = scene.mesh()
    result = stcontact.solve(scene, solver="fas-apriori")
    assert result.converged and result.error <= 1e-6
    assert len(result.master_nodes) == len(result.contact_nodes) == len(mesh["master_nodes"]) == 21
    nodes = mesh["nodes"]
    # Mirror pairs along y: the same x, the master below.
    np.testing.assert_array_equal(nodes[result.contact_nodes, 0], nodes[result.master_nodes, 0])
    assert (nodes[result.contact_nodes, 1] > nodes[result.master_nodes, 1]).all()


def test_non_matching_faces_pair_node_to_segment():
    """Each pad node meets the specimen's face at the point its weights give, right below it."""
    scene = stcontact.load_scene(SCENES / "fretting_pad.toml", sets=[
        "mesh.file=../meshes/fretting_pad_nonmatching_small.msh", "contact.pairing=segment", "time.steps=21"])
    mesh = scene.mesh()
    facets, weights, nodes = mesh["master_facets"], mesh["master_weights"], mesh["nodes"]
    assert facets.shape == weights.shape == (len(mesh["contact_nodes"]), 2)
    np.testing.assert_allclose(weights.sum(axis=1), 1.0, rtol=0, atol=1e-15)
    assert ((weights > 0) == (facets >= 0)).all()
    points = np.einsum("ij,ijk->ik", weights, nodes[np.where(facets >= 0, facets, 0)])
    np.testing.assert_allclose(points[:, 0], nodes[mesh["contact_nodes"], 0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(mesh["initial_gap"], nodes[mesh["contact_nodes"], 1] - points[:, 1], rtol=0, atol=1e-12)
    result = stcontact.solve(scene, solver="fas-apriori")
    assert result.converged and result.error <= 1e-6


def test_one_body_has_no_master_nodes():
    scene = stcontact.load_scene(SCENES / "hemicylinder.toml", sets=SMALL)
    assert len(scene.mesh()["master_nodes"]) == 0


def test_a_moving_obstacles_displacements_are_in_the_scenes_frame():
    scene = stcontact.load_scene(SCENES / "moving_pad.toml", sets=["mesh.arc_nodes=21", "time.steps=81", "output.frames=false"])
    result = stcontact.solve(scene, solver="incremental")
    assert result.converged
    u = result.displacement_fields()
    mesh = scene.mesh()
    # The held top does not move in the scene's frame (it moves by -d(t) in the pad's).
    top = np.flatnonzero(np.isclose(mesh["nodes"][:, 1], 0.0))
    assert len(top) > 2
    assert np.abs(u[2 * top]).max() == 0.0 and np.abs(u[2 * top + 1]).max() == 0.0
    assert result.reactions["normal_force"].max() > 0.0


def test_a_polyline_scene_solves():
    result = stcontact.solve(stcontact.load_scene(SCENES / "groove.toml", sets=SMALL), solver="fas-apriori")
    assert result.converged and result.error <= 1e-6
