#!/usr/bin/env python3
"""Description: Cattaneo-Mindlin partial slip of two identical elastic cylinders (docs/two_bodies.md,
  "Validation"): examples/scenes/two_cylinders.toml at 801 arc nodes, pressed to a fixed approach
  with mu = 0.5, then driven sideways at that approach so that the tangential force Q grows toward muP.
  Identical bodies have Dundurs' beta = 0, where Cattaneo's stick zone c/a = sqrt(1 - Q/muP) is exact.
  Solved by the incremental solver with the stcontact Python module; writes into the output folder:
    stick_zone.png  left: c/a against Q/muP, from the traction deficit's moments and from the extent
                    of the sticking nodes, with Cattaneo's; right: each contact node's state (stick,
                    slip) at each instant, x/a against Q/muP, with Cattaneo's stick/slip boundary
    stick_zone.csv  one row per instant: Q/muP, a, c/a (moments), c/a (sticking nodes), Cattaneo's
  and prints the stick zone at Q/muP = 0.2, 0.5, 0.8. Exits with status 1 when the solve does not
  converge.
Sample run:
  PYTHONPATH=build/python /usr/bin/python3 examples/python/cattaneo_stick_zone.py results/cattaneo
  PYTHONPATH=build/python /usr/bin/python3 examples/python/cattaneo_stick_zone.py /tmp/c --arc-nodes 201
Options: --arc-nodes N (default 801).
"""

import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import stcontact  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.normpath(os.path.join(HERE, "..", "scenes", "two_cylinders.toml"))
PRESS, SLIDE = 10, 400          # instants of pressing, then of the sideways drive
APPROACH = 0.036                # the upper top's descent: the 0.02 gap closed, then 0.008 into each body
DRIVE = 0.015                   # the upper top's sideways drive at the end: Q reaches muP
FRICTION = 0.5


def sets(arc_nodes):
    t_press = PRESS / (PRESS + SLIDE)
    return [f"mesh.arc_nodes={arc_nodes}", "mesh.grading=1.05", f"contact.friction={FRICTION}",
            f"time.steps={PRESS + SLIDE + 1}", "output.frames=false",
            f"dirichlet[2].times=[0.0, {t_press!r}, 1.0]", f"dirichlet[2].values=[0.0, 0.0, {DRIVE!r}]",
            f"dirichlet[3].times=[0.0, {t_press!r}, 1.0]", f"dirichlet[3].values=[0.0, {-APPROACH!r}, {-APPROACH!r}]"]


def semicircle(x, w, h):
    """Centre and half-width of w(x) ~ sqrt(1 - (x - e)^2 / a^2) from its moments (P1 nodal forces:
    a^2 = 4 (sum w x^2 / sum w - e^2 - h^2 / 6); tests/validation/validation_support.hpp)."""
    total = w.sum()
    if not total > 0:  # full slip: no deficit
        return 0.0, 0.0
    e = (w * x).sum() / total
    return e, np.sqrt(max(4.0 * ((w * x * x).sum() / total - e * e - h * h / 6.0), 0.0))


def stick_zones(result, x, h):
    """Per sideways instant: Q/muP, a, c/a from the deficit's moments, c/a from the sticking nodes,
    and each node's state (0 open, 1 stick, 2 slip)."""
    rows, states = [], []
    normal, tangential = result.normal_forces, result.tangential_forces
    for k in range(PRESS + 1, normal.shape[1]):
        p, t = normal[:, k], tangential[:, k]
        sign = 1.0 if t.sum() >= 0 else -1.0
        _, a = semicircle(x, p, h)
        _, c = semicircle(x, FRICTION * p - sign * t, h)
        closed = p > 1e-12 * p.max()
        slip = closed & (np.abs(t) >= FRICTION * p * (1 - 1e-9))
        stick = closed & ~slip
        extent = (x[stick].max() - x[stick].min()) / 2 if stick.any() else 0.0
        ratio = abs(t.sum()) / (FRICTION * p.sum())
        rows.append((ratio, a, c / a, extent / a, np.sqrt(max(0.0, 1.0 - ratio))))
        states.append(np.where(slip, 2, np.where(stick, 1, 0)))
    return np.array(rows), np.array(states)


def draw(rows, states, x, out):
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    left.plot(rows[:, 0], rows[:, 2], label="model: traction deficit's moments")
    left.plot(rows[:, 0], rows[:, 3], ".", markersize=2, label="model: sticking nodes' extent")
    left.plot(rows[:, 0], rows[:, 4], "k--", label="Cattaneo: √(1 − Q/μP)")
    left.set(xlabel="Q / μP", ylabel="c / a", title="Stick zone of two identical cylinders (β = 0)")
    a = np.median(rows[:, 1])
    shown = np.abs(x) <= 1.2 * a
    colours = matplotlib.colors.ListedColormap(["white", "tab:blue", "tab:orange"])
    right.pcolormesh(x[shown] / a, rows[:, 0], states[:, shown], cmap=colours, vmin=0, vmax=2, shading="nearest")
    boundary = np.sqrt(np.clip(1 - rows[:, 0], 0, None))
    right.plot(boundary, rows[:, 0], "k--", label="Cattaneo: |x| = c")
    right.plot(-boundary, rows[:, 0], "k--")
    right.plot([], [], "s", color="tab:blue", label="stick")
    right.plot([], [], "s", color="tab:orange", label="slip")
    right.set(xlabel="x / a", ylabel="Q / μP", title="Contact nodes: stick and slip")
    for axes in (left, right):
        axes.legend(fontsize=8, loc="lower left" if axes is left else "upper right")
    left.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stick_zone.png"), dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("Sample run:")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="output folder (created)")
    parser.add_argument("--arc-nodes", type=int, default=801)
    args = parser.parse_args()
    if args.arc_nodes < 21:
        parser.error("--arc-nodes must be >= 21")
    os.makedirs(args.out, exist_ok=True)
    scene = stcontact.load_scene(SCENE, sets=sets(args.arc_nodes))
    mesh = scene.mesh()
    x = mesh["nodes"][mesh["contact_nodes"], 0]
    result = stcontact.solve(scene, "incremental", reference=False)
    if not result.converged:
        sys.exit(f"the incremental solve did not converge ({result.termination})")
    h = np.pi / (args.arc_nodes + 1)  # the arc's node spacing, R = 1 (src/mesh/half_disc.hpp)
    rows, states = stick_zones(result, x, h)
    with open(os.path.join(args.out, "stick_zone.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["q_over_mu_p", "a", "c_over_a_moments", "c_over_a_nodes", "c_over_a_cattaneo"])
        writer.writerows([[f"{v:.6g}" for v in row] for row in rows])
    for target in (0.2, 0.5, 0.8):
        ratio, a, moments, nodes, theory = rows[np.argmin(np.abs(rows[:, 0] - target))]
        print(f"Q/muP {ratio:.3f}: c/a {moments:.4f} (moments), {nodes:.4f} (sticking nodes), Cattaneo {theory:.4f}; "
              f"|c - c_Cattaneo| = {abs(moments - theory) * a / h:.2f} h")
    draw(rows, states, x, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
