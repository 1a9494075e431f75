"""3D scenes through the module: the sizes check() gives, the interface layout of a solve (three rows
per contact node, the second tangential component), the mesh arrays, and the 2D-only refusal."""

import numpy as np
import pytest

import stcontact
from conftest import SEED_SCENE, SMALL, SOURCE_DIR

HEMISPHERE = SOURCE_DIR / "examples" / "scenes" / "hemisphere.toml"
SMALL_3D = ["mesh.divisions=3", "time.steps=11", "output.frames=false"]


def test_check_gives_the_dimension_and_the_interface_rows():
    sizes = stcontact.check(HEMISPHERE)
    assert sizes["dimension"] == 3
    assert sizes["contact_nodes"] == 737
    assert sizes["interface_rows"] == 3 * 737
    assert sizes["plane"] == "none"


def test_solve_has_three_rows_per_contact_node():
    result = stcontact.solve(stcontact.load_scene(HEMISPHERE, sets=SMALL_3D), solver="incremental")
    assert result.converged and result.dimension == 3
    n_c, m = len(result.contact_nodes), len(result.times)
    assert result.interface_forces.shape == (3 * n_c, m)
    assert result.tangential_forces_2.shape == (n_c, m)
    np.testing.assert_array_equal(result.tangential_forces_2, result.interface_forces[2::3])
    assert "%d contact nodes x %d instants" % (n_c, m) in repr(result)  # not 3 n_c / 2
    # The scene is symmetric about y = 0 and slides along x: no resultant along tau_2 = e_y.
    assert np.abs(result.reactions["tangential_force_2"]).max() < 1e-10 * result.reactions["normal_force"].max()
    # On the plane z = const the global resultant is (tangential, tangential_2, normal).
    for key, column in (("force_x", "tangential_force"), ("force_y", "tangential_force_2"), ("force_z", "normal_force")):
        np.testing.assert_allclose(result.reactions[key], result.reactions[column], rtol=0,
                                   atol=1e-12 * result.reactions["normal_force"].max())


def test_mesh_gives_tetrahedra():
    mesh = stcontact.load_scene(HEMISPHERE, sets=SMALL_3D).mesh()
    assert mesh["nodes"].shape[1] == 3 and mesh["tetrahedra"].shape[1] == 4
    assert "triangles" not in mesh


def test_second_tangential_component_is_refused_in_2d():
    result = stcontact.solve(stcontact.load_scene(SEED_SCENE, sets=SMALL), solver="incremental")
    assert result.dimension == 2
    with pytest.raises(ValueError, match="3D scenes only"):
        result.tangential_forces_2
