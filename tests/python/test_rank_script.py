"""scripts/rank_against_sparse_solves.py, which docs/floor.md quotes: its epsilon-rank on singular
values whose tails are known, and one row on a small seed scene that agrees with a solve of its own."""

import numpy as np
import stcontact
from conftest import SEED_SCENE, SMALL, load_script


def test_epsilon_rank_is_the_shortest_head_whose_tail_is_within_eps():
    script = load_script("rank_against_sparse_solves.py")
    values = np.array([1.0, 1e-2, 1e-4, 1e-8])  # energies 1, 1e-4, 1e-8, 1e-16
    assert script.epsilon_rank(values, 1e-3) == 1   # tail 1e-4 + ... = 1.0001e-4 <= 1e-3 x 1.0001
    assert script.epsilon_rank(values, 1e-6) == 2   # tail 1e-8 + 1e-16
    assert script.epsilon_rank(values, 1e-12) == 3  # tail 1e-16
    assert script.epsilon_rank(values, 0.0) == 4
    assert script.epsilon_rank(values, 1.0) == 0


def test_a_row_gives_the_rank_of_the_incremental_forces_and_the_solves_fas_apriori_spent():
    script = load_script("rank_against_sparse_solves.py")
    row = script.measure("small", str(SEED_SCENE), SMALL)
    cells = [cell.strip() for cell in row.strip("|").split("|")]
    scene = stcontact.load_scene(SEED_SCENE).with_sets(*SMALL)
    forces = stcontact.solve(scene, "incremental").interface_forces
    rank = script.epsilon_rank(np.linalg.svd(forces, compute_uv=False), 1e-6)
    solved = stcontact.solve(scene, "fas-apriori", tol=1e-6, spatial_modes=False)  # as the script's `compare`
    assert cells[0] == "small" and cells[1] == f"{forces.shape[0]} x {forces.shape[1]}"
    assert int(cells[2]) == rank and 0 < rank <= min(forces.shape)
    assert int(cells[4]) == solved.summary["sparse_solves"] > 0
    assert cells[7] == "converged"
