#!/usr/bin/env python3
"""Sparse solves against the rank of the solution (docs/scale.md, "Solves at the rank").

For each scene and size, fas-apriori solves to its tolerance (no reference, no frames) and the
converged interface force history Λ (d n_C x m) gives its epsilon-ranks: the fewest leading singular
values whose tail energy sum_{i>r} s_i^2 is at most eps sum s_i^2, for eps = 1e-6 (the target's) and
1e-12 (the tolerance's square, what a solve to 1e-6 has to resolve). Printed as a Markdown table:
sparse solves, the two ranks, and solves / rank(1e-6).

  python3 scripts/solves_at_the_rank.py                       # the hemisphere and its fretting, 8 to 16
  python3 scripts/solves_at_the_rank.py --divisions 8 12 --linear cg-gamg

Needs the Python module (PYTHONPATH=build/python). Counts are deterministic: run it beside anything.
"""
import argparse
import json
import os

import numpy as np

import stcontact

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = {"hemisphere": "examples/scenes/hemisphere.toml", "hemisphere_fretting": "examples/scenes/hemisphere_fretting.toml"}


def epsilon_rank(singular_values, eps):
    """The fewest leading modes whose tail energy is at most eps of the whole."""
    energy = singular_values ** 2
    tail = np.cumsum(energy[::-1])[::-1]  # tail[i] = sum_{j >= i} s_j^2
    total = tail[0] if tail.size else 0.0
    return int(np.count_nonzero(tail > eps * total))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", nargs="+", default=list(SCENES), choices=list(SCENES))
    parser.add_argument("--divisions", nargs="+", type=int, default=[8, 12, 16])
    parser.add_argument("--linear", default="auto", help="solver.linear (default auto)")
    args = parser.parse_args()
    print("| scene | divisions | instants | sparse solves | relaxations | rank (1e-6) | rank (1e-12) | solves / rank (1e-6) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name in args.scenes:
        for divisions in args.divisions:
            sets = [f"mesh.divisions={divisions}", "output.frames=false", f'solver.linear="{args.linear}"']
            result = stcontact.solve(os.path.join(ROOT, SCENES[name]), "fas-apriori", sets=sets, reference=False,
                                     spatial_modes=False)
            summary = result.summary
            forces = result.interface_forces
            forces = forces[np.any(forces != 0.0, axis=1)]  # the rows that ever carry a force
            s = np.linalg.svd(forces, compute_uv=False)
            r6, r12 = epsilon_rank(s, 1e-6), epsilon_rank(s, 1e-12)
            print(f"| {name} | {divisions} | {forces.shape[1]} | {summary['sparse_solves']} | {summary['relaxations']} | "
                  f"{r6} | {r12} | {summary['sparse_solves'] / max(r6, 1):.1f} |", flush=True)
            assert summary["termination"] == "converged", json.dumps(summary["message"])


if __name__ == "__main__":
    main()
