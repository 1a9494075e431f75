"""scripts/directions_span.py, which docs/scale.md quotes ("What the directions span"): the dimension of
the mirror-symmetric zone vectors on a case counted by hand, and on the shallow press at divisions 8 a
stage without a trailing block whose directions stay in that space and fill it."""

import numpy as np
import pytest
import stcontact
from conftest import load_script


def test_the_symmetric_dimension_counts_the_pairs_and_the_nodes_on_the_plane():
    script = load_script("directions_span.py")
    # Nodes 0 and 1 mirror each other in y, node 2 lies on the plane y = 0; frames the identity.
    points = np.array([[0.5, 1.0, 0.0], [0.5, -1.0, 0.0], [0.0, 0.0, 0.0]])
    F = np.repeat(np.eye(3)[None], 3, axis=0)
    zone = np.arange(3)
    # Symmetric vectors: w_1 = M w_0 and w_2 = M w_2 (its y row zero): 3 + 2 = 5 of 9 rows,
    # (9 + tr M) / 2 with tr M = 1 from node 2.
    M = np.diag([1.0, -1.0, 1.0])
    w0 = np.array([1.0, 2.0, 3.0])
    symmetric = np.concatenate([w0, M @ w0, [4.0, 0.0, 5.0]])[:, None]
    dimension, defect = script.symmetry_of(symmetric, F, points, zone)
    assert dimension == 5 and defect < 1e-15
    asymmetric = symmetric.copy()
    asymmetric[4, 0] += 1.0  # node 1's y row no longer mirrors node 0's
    dimension, defect = script.symmetry_of(asymmetric, F, points, zone)
    assert defect > 0.1 and dimension == 9  # no mirror keeps it: every row


def test_without_a_trailing_block_the_directions_fill_the_symmetric_zone_space():
    script = load_script("directions_span.py")
    try:
        row = script.measure("hemisphere_shallow", 8, "mumps")
    except stcontact.InputError as error:  # a build without PETSc
        pytest.skip(str(error))
    # The iterates of a mirror-symmetric scene are symmetric: so is every direction (to the solves'
    # round-off), and they are independent, so never more than the space's dimension.
    assert row["defect"] < 1e-8
    assert row["rank"] == row["directions"] <= row["dimension"] < row["rows"]
    # What the docs measure: the directions end by spanning it (34 of 34 here).
    assert row["directions"] >= 0.9 * row["dimension"]
    assert row["solves"] == row["directions"] + 3  # and the three load responses
