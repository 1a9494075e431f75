#!/usr/bin/env python3
"""What the separated stage's directions span without a trailing block (docs/scale.md, "Solves at the rank").

For each scene and size, fas-apriori solves to its tolerance on a backend without a trailing block
(solver.linear = "mumps" by default: exact solves, one per direction, as on cg-gamg) and its directions
Z (d n_C x p, interface_directions) are compared with the space the iterates' right-hand sides
w = lambda_hat + k v_hat can live in: the rows of the contact zone (the nodes the directions touch),
less what the scene's mirror symmetry keeps out. A reflection M that maps the zone's nodes onto
themselves maps a nodal vector w_i (in the node's frame F_i = [n_i, tau_i1, tau_i2]) to
w_j = F_j^T M F_i w_i at the mirror node j; the iterates of a symmetric scene are symmetric, and the
symmetric vectors form the +1 eigenspace of that involution R, of dimension (d |Z| + tr R) / 2, where
tr R sums tr(F_i^T M F_i) over the nodes on the mirror plane. Printed as a Markdown table: the zone's
nodes, those that ever close, d |Z|, the dimension of the space (the symmetric vectors when Z is
symmetric under a mirror, else every row), the directions p, how far Z is from symmetric, and the
solves and relaxations.

  PYTHONPATH=build/python python3 scripts/directions_span.py
  PYTHONPATH=build/python python3 scripts/directions_span.py --runs hemisphere:16 --linear cg-gamg

Needs the Python module (PYTHONPATH=build/python) and h5py. Counts are deterministic: run it beside anything.
"""
import argparse
import os
import tempfile

import h5py
import numpy as np

import stcontact

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUNS = ["hemisphere:8", "hemisphere:12", "hemisphere_fretting:8", "hemisphere_fretting:12", "hemisphere_shallow:12"]


def frames(h5):
    """F_i = [n_i, tau_i1, tau_i2] as columns, n_C x 3 x 3 (3D)."""
    normals = h5["contact/normals"][()]
    tangents = h5["contact/tangents"][()].reshape(len(normals), 2, 3)
    return np.concatenate([normals[:, None, :], tangents], axis=1).transpose(0, 2, 1)


def mirrors(points, scale):
    """Every coordinate reflection M that maps the points onto themselves: (M, j), j[i] the image of i."""
    keys = {tuple(np.round(p / scale, 6)): i for i, p in enumerate(points)}
    for axis in range(points.shape[1]):
        M = np.eye(points.shape[1])
        M[axis, axis] = -1.0
        images = [keys.get(tuple(np.round(M @ p / scale, 6))) for p in points]
        if all(j is not None for j in images):
            yield M, np.array(images)


def symmetric_dimension_and_defect(Z, F, zone, M, image):
    """dim of the zone vectors symmetric under M, and max over Z's columns of |w_j - T_i w_i| / |w|."""
    d = 3
    trace = 0.0
    defect = 0.0
    blocks = Z.reshape(-1, d, Z.shape[1])  # node, component, direction
    norm = np.linalg.norm(Z, axis=0)
    for i in zone:
        j = image[i]
        T = F[j].T @ M @ F[i]
        if j == i:
            trace += np.trace(T)
        defect = max(defect, float(np.max(np.linalg.norm(blocks[j] - T @ blocks[i], axis=0) / norm)))
    return int(round((d * len(zone) + trace) / 2)), defect


SYMMETRIC = 1e-6  # Z's asymmetry below which its directions count as symmetric (the solves' noise)


def symmetry_of(Z, F, points, zone):
    """(dimension, defect): the reflection of the zone under which Z is most nearly symmetric (the
    mesh may map onto itself under reflections that its cells, the obstacle or the loading break) and
    Z's asymmetry under it (nan when none maps the zone onto itself); the dimension is that of the
    symmetric vectors when Z is symmetric (within SYMMETRIC), else the zone's every row, d |Z|."""
    best = (3 * len(zone), float("nan"))
    for M, image in mirrors(points[zone], np.max(np.abs(points))):
        found = symmetric_dimension_and_defect(Z, F, zone, M, dict(zip(zone, zone[image])))
        if not found[1] >= best[1]:  # the smaller defect (nan: none yet)
            best = found
    return best if best[1] <= SYMMETRIC else (3 * len(zone), best[1])


def measure(name, divisions, linear):
    """One row: fas-apriori on examples/scenes/<name>.toml at `divisions`, solver.linear = `linear`."""
    sets = ([f"mesh.divisions={divisions}"] if divisions else []) + ["output.frames=false", f'solver.linear="{linear}"']
    with tempfile.TemporaryDirectory() as out:
        result = stcontact.solve(os.path.join(ROOT, "examples/scenes", name + ".toml"), "fas-apriori", sets=sets,
                                 reference=False, spatial_modes=False, out=out)
        assert result.summary["termination"] == "converged", result.summary["message"]
        with h5py.File(os.path.join(out, "solution.h5")) as h5:
            points = h5["mesh/points"][()][h5["contact/nodes"][()]]
            F = frames(h5)
            closed = int(np.count_nonzero((h5["interface/state"][()] > 0).any(axis=0)))
    Z = result.interface_directions
    zone = np.flatnonzero(np.any(Z.reshape(-1, 3, Z.shape[1]) != 0.0, axis=(1, 2)))
    dimension, defect = symmetry_of(Z, F, points, zone)
    return {"zone": len(zone), "closed": closed, "rows": 3 * len(zone), "dimension": dimension,
            "directions": Z.shape[1], "rank": int(np.linalg.matrix_rank(Z)), "defect": defect,
            "solves": result.summary["sparse_solves"], "relaxations": result.summary["relaxations"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", nargs="+", default=RUNS, help="scene:divisions (examples/scenes/<scene>.toml; scene: for its own mesh)")
    parser.add_argument("--linear", default="mumps", help="solver.linear (default mumps)")
    args = parser.parse_args()
    print("| scene | divisions | zone nodes | ever closed | d \\|Z\\| | the space's dimension | directions p | "
          "rank of Z | Z's asymmetry | sparse solves | relaxations |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for run in args.runs:
        name, divisions = run.split(":")
        r = measure(name, divisions, args.linear)
        print(f"| {name} | {divisions} | {r['zone']} | {r['closed']} | {r['rows']} | {r['dimension']} | "
              f"{r['directions']} | {r['rank']} | {r['defect']:.1e} | {r['solves']} | {r['relaxations']} |", flush=True)


if __name__ == "__main__":
    main()
