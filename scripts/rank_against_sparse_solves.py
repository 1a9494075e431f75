#!/usr/bin/python3
"""How many sparse solves fas-apriori spends against the rank of what it computes.

For each scene: the epsilon-rank of the converged interface force history (the incremental solver's
lambda, d n_C x m, its singular values in the Euclidean norm: the smallest r with
sum_{i > r} s_i^2 <= eps * sum_i s_i^2), for eps = 1e-6 and 1e-12, beside the sparse solves
(right-hand sides of the sparse factor) fas-apriori spends in a solve at tolerance tau = 1e-6, which
stops on its own estimate, as `stcontact solve` makes it (through `compare`, which, like the command
line, asks for no spatial modes: their responses would add solves where the interface is condensed).
The SVD verifies; it is never used to solve. Prints a Markdown table.

    PYTHONPATH=build/python /usr/bin/python3 scripts/rank_against_sparse_solves.py [--large]

--large adds the hemisphere at divisions 16 (its incremental solve takes about 30 s here).
"""
import os
import sys

import numpy as np
import stcontact

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # study_scenes.py, also when loaded by path
from study_scenes import ARC_NODES_801, ARC_NODES_1601, HEMISPHERE_8, HEMISPHERE_12, HEMISPHERE_16, SEED_SCENE

SCENES = [SEED_SCENE, ARC_NODES_801, ARC_NODES_1601, HEMISPHERE_8, HEMISPHERE_12]
LARGE = [HEMISPHERE_16]
TOLERANCE = 1e-6


def epsilon_rank(singular_values, eps):
    """The smallest r whose tail sum_{i > r} s_i^2 is at most eps times the whole."""
    energy = singular_values**2
    tail = np.concatenate([np.cumsum(energy[::-1])[::-1], [0.0]])  # tail[r] = sum_{i >= r} s_i^2
    return int(np.argmax(tail <= eps * tail[0]))


def measure(label, path, sets):
    scene = stcontact.load_scene(path).with_sets(*sets, "output.frames=false")
    exact = stcontact.solve(scene, "incremental")
    singular_values = np.linalg.svd(exact.interface_forces, compute_uv=False)
    solved = stcontact.compare(scene, "fas-apriori", repeats=1, tol=TOLERANCE).summary[0]
    spent = solved["sparse_solves"]
    rank = epsilon_rank(singular_values, 1e-6)
    return (f"| {label} | {exact.interface_forces.shape[0]} x {exact.interface_forces.shape[1]} | {rank} | "
            f"{epsilon_rank(singular_values, 1e-12)} | {spent} | {spent / rank:.1f} | "
            f"{solved['relaxations']} | {solved['termination']} |")


def main():
    scenes = SCENES + (LARGE if "--large" in sys.argv[1:] else [])
    print("| scene | λ (d n_C x m) | ε-rank, ε = 1e-6 | ε = 1e-12 | fas-apriori sparse solves (τ = 1e-6) |"
          " ÷ ε-rank (1e-6) | relaxations | termination |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    for label, path, sets in scenes:
        print(measure(label, path, sets), flush=True)


if __name__ == "__main__":
    main()
