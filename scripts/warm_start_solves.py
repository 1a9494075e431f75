#!/usr/bin/env python3
"""Description: does a better start cut fas-apriori's sparse solves? (docs/scale.md, "A ceiling on the
target"). Solves a scene at mesh.divisions F cold, then warm-started from
  - its own converged forces and displacements (no directions),
  - a solve at divisions C: its forces (as densities over the tributary areas), displacements and,
    in a second run, its interface directions, carried to the fine contact nodes by inverse-distance
    weighting of the three nearest coarse ones in the plane x-y (the half-ball's contact face),
and prints one Markdown row per run: relaxations, sparse solves, estimate, and the distance of the
start's forces and of the converged ones to the cold solve's.
Sample run (about a minute; MUMPS makes the solves of cg-gamg in one process):
  PYTHONPATH=build/python python3 scripts/warm_start_solves.py --coarse 6 --fine 12
"""
import argparse
import types

import numpy as np
import stcontact


def contact_xy(scene):
    mesh = scene.mesh()
    return mesh["nodes"][mesh["contact_nodes"]][:, :2]


def carried(values, coarse_xy, fine_xy, neighbours=3):
    """values (n_coarse x m) at the fine nodes: inverse-distance weights of the nearest coarse nodes."""
    distance = np.linalg.norm(fine_xy[:, None, :] - coarse_xy[None, :, :], axis=2)
    nearest = np.argsort(distance, axis=1)[:, :neighbours]
    weight = 1.0 / np.maximum(np.take_along_axis(distance, nearest, axis=1), 1e-12)
    weight /= weight.sum(axis=1, keepdims=True)
    return np.einsum("fk,fkm->fm", weight, values[nearest])


def carried_rows(rows, coarse, fine, per_area):
    """d n_C x m interface rows (row d i + j: component j of node i) carried from `coarse` to `fine`,
    each (contact xy, SolveResult); forces and directions as densities over the tributary areas
    when per_area."""
    (coarse_xy, coarse_result), (fine_xy, fine_result) = coarse, fine
    d = coarse_result.dimension
    out = np.zeros((d * len(fine_xy), rows.shape[1]))
    for j in range(d):
        part = rows[j::d] / coarse_result.tributary[:, None] if per_area else rows[j::d]
        out[j::d] = carried(part, coarse_xy, fine_xy)
        if per_area:
            out[j::d] *= fine_result.tributary[:, None]
    return np.asfortranarray(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="examples/scenes/hemisphere.toml")
    parser.add_argument("--coarse", type=int, default=6)
    parser.add_argument("--fine", type=int, default=12)
    parser.add_argument("--linear", default="mumps")
    parser.add_argument("--tol", type=float, default=1e-6)
    a = parser.parse_args()
    sets = [f'solver.linear="{a.linear}"', "output.frames=false"]
    scene = {n: stcontact.load_scene(a.scene, sets=sets + [f"mesh.divisions={n}"]) for n in (a.coarse, a.fine)}

    def solve(n, start=None, seed_basis=False):
        return stcontact.solve(scene[n], "fas-apriori", tol=a.tol, reference=False, spatial_modes=False,
                               start=start, seed_basis=seed_basis)

    coarse, cold = solve(a.coarse), solve(a.fine)
    pair = ((contact_xy(scene[a.coarse]), coarse), (contact_xy(scene[a.fine]), cold))
    start = types.SimpleNamespace(
        interface_forces=carried_rows(coarse.interface_forces, *pair, True),
        interface_displacements=carried_rows(coarse.interface_displacements, *pair, False),
        interface_directions=carried_rows(coarse.interface_directions, *pair, True))
    forces = cold.interface_forces

    def distance(f):
        return np.linalg.norm(f - forces) / np.linalg.norm(forces)

    runs = [("cold", cold, None),
            ("its own converged histories", solve(a.fine, start=cold), cold.interface_forces),
            (f"divisions {a.coarse}'s histories", solve(a.fine, start=start), start.interface_forces),
            (f"divisions {a.coarse}'s histories and {start.interface_directions.shape[1]} directions",
             solve(a.fine, start=start, seed_basis=True), start.interface_forces)]
    print(f"{a.scene} at divisions {a.fine} ({a.linear}, τ = {a.tol:g}); divisions {a.coarse}: "
          f"{coarse.summary['relaxations']} relaxations, {coarse.summary['sparse_solves']} sparse solves\n")
    print("| start | relaxations | sparse solves | estimate | start's forces to cold's | converged to cold's |")
    print("|---|---:|---:|---:|---:|---:|")
    for name, r, start_forces in runs:
        s = r.summary
        from_start = "–" if start_forces is None else f"{distance(start_forces):.2g}"
        print(f"| {name} | {s['relaxations']} | {s['sparse_solves']} | {s['error_estimate']:.2g} | {from_start} | "
              f"{distance(r.interface_forces):.1e} |")


if __name__ == "__main__":
    main()
