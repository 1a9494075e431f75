#!/usr/bin/env python3
"""What solving each direction only as accurately as its weight requires could save (docs/scale.md,
"Solves at the rank").

On an iterative backend every direction z_i of the separated stage is a Krylov solve to the relative
residual rho (solver.linear_rtol, derived from the tolerance). The displacement it contributes is
x_i c_i (c_i its row of the stage's coordinates, c = Z^T k^-1 w), so a solve of direction i to rho_i
instead of rho moves the stage's displacement by at most about rho_i a_i, a_i = |z_i| |c_i| (the
triangle bound behind the uniform rule, docs/method.md §2, "Inexact linear solves"). Any per-direction
rule that keeps the uniform rule's bound, sum_i rho_i a_i <= rho sum_i a_i, costs at least the Krylov
work of the allocation that minimises sum_i log(1 / rho_i) under it: equal shares, rho_i = rho a_mean / a_i
(Lagrange), here clipped to [rho, 1]. With iterations in proportion to the decades a solve reduces
its residual by, that gives the largest share of Krylov iterations such a rule can save, even knowing
the converged weights in advance (the weights of the last solve; a rule that learns them on the way
refines and pays more).

For each size, fas-apriori solves the hemisphere to its tolerance on the given backend (no reference,
no frames); w = lambda + k v of the converged history. Printed as a Markdown table.

  PYTHONPATH=build/python python3 scripts/inexact_directions_bound.py
  PYTHONPATH=build/python python3 scripts/inexact_directions_bound.py --divisions 8 --scene hemisphere_fretting

Needs the Python module (PYTHONPATH=build/python) built with PETSc for cg-gamg.
"""
import argparse
import json
import os

import numpy as np

import stcontact

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = {"hemisphere": "examples/scenes/hemisphere.toml", "hemisphere_fretting": "examples/scenes/hemisphere_fretting.toml"}


def largest_saving(weights, rho):
    """1 - (Krylov decades of the equal-share allocation) / (decades at rho for every direction)."""
    weights = weights[weights > 0.0]
    shares = np.clip(rho * weights.mean() / weights, rho, 1.0)
    return 1.0 - np.log10(1.0 / shares).sum() / (weights.size * np.log10(1.0 / rho))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="hemisphere", choices=list(SCENES))
    parser.add_argument("--divisions", nargs="+", type=int, default=[8, 12])
    parser.add_argument("--linear", default="cg-gamg", help="solver.linear (default cg-gamg)")
    args = parser.parse_args()
    print("| scene | divisions | directions | Krylov iterations | rho | weights within 10x / 100x of their mean | "
          "largest saving of Krylov iterations |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for divisions in args.divisions:
        sets = [f"mesh.divisions={divisions}", "output.frames=false", f'solver.linear="{args.linear}"']
        scene = stcontact.load_scene(os.path.join(ROOT, SCENES[args.scene]), sets=sets)
        result = stcontact.solve(scene, "fas-apriori", reference=False, spatial_modes=False)
        summary = result.summary
        assert summary["termination"] == "converged", json.dumps(summary["message"])
        k = scene.mesh()["search_direction"]
        Z = result.interface_directions
        w = result.interface_forces + k[:, None] * result.interface_displacements
        c = Z.T @ (w / k[:, None])
        weights = np.linalg.norm(Z, axis=0) * np.linalg.norm(c, axis=1)
        rho = max(1e-12, 1e-4 * scene.check()["tolerance"])  # LinearSolverOptions::residualTolerance
        near = [np.mean((weights >= weights.mean() / f) & (weights <= weights.mean() * f)) for f in (10, 100)]
        print(f"| {args.scene} | {divisions} | {Z.shape[1]} | {summary['krylov_iterations']} | {rho:.0e} | "
              f"{near[0]:.0%} / {near[1]:.0%} | {largest_saving(weights, rho):.0%} |", flush=True)


if __name__ == "__main__":
    main()
