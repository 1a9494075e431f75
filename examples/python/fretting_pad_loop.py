#!/usr/bin/env python3
"""Description: the fretting pad (examples/scenes/fretting_pad.toml) on refined meshes against Mindlin's
  hysteresis loop in plane strain (docs/two_bodies.md, "Mindlin's loop in 2D"). For each node spacing h
  of the faces, the mesh is the committed one (h = 0.02, 0.01) or made by examples/meshes/fretting_pad.py
  (needs the Debian 12 package python3-gmsh) in OUT/meshes; the scene is solved by the incremental
  solver with the stcontact Python module. Writes into the output folder:
    loop.csv   one row per mesh: a/h, Q*/muP, the loop's area and width at Q = 0 against Mindlin's
    loop.png   left: the loops, Q/muP against the drive less the chord between the loop's tips (the
               finite bodies' linear compliance, which hides the loop); right: their width delta_u(Q) - delta_l(Q)
               against Q/Q*, with the closed form (the quantity of the loop that does not depend on
               the bodies' size in 2D)
  and prints the table. Exits with status 1 when a solve does not converge.
Sample run:
  PYTHONPATH=build/python /usr/bin/python3 examples/python/fretting_pad_loop.py results/fretting_pad
  PYTHONPATH=build/python /usr/bin/python3 examples/python/fretting_pad_loop.py /tmp/pad --h 0.02,0.01
  PYTHONPATH=build/python /usr/bin/python3 examples/python/fretting_pad_loop.py results/fretting_pad_nonmatching \\
      --specimen-ratio 0.65
Options: --h LIST (comma-separated node spacings, default 0.02,0.01,0.005,0.0025); --specimen-ratio R
  (the specimen's face nodes R h apart, not below the pad's: non-matching faces, contact.pairing =
  "segment"; default 0, matching).
"""

import argparse
import csv
import os
import subprocess
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import stcontact  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.normpath(os.path.join(HERE, "..", "scenes", "fretting_pad.toml"))
MESHES = os.path.normpath(os.path.join(HERE, "..", "meshes"))
COMMITTED = {(0.02, 0.0): "fretting_pad_small.msh", (0.01, 0.0): "fretting_pad.msh",
             (0.02, 0.65): "fretting_pad_nonmatching_small.msh"}
PRESS_STEPS, QUARTER = 20, 16  # the scene's instants: pressing, then each quarter cycle


def mesh_for(h, ratio, out):
    """The committed mesh of spacing h (the specimen's ratio h, 0: matching), or one made by the mesh
    script in out/meshes."""
    if (h, ratio) in COMMITTED:
        return os.path.join(MESHES, COMMITTED[(h, ratio)])
    os.makedirs(os.path.join(out, "meshes"), exist_ok=True)
    path = os.path.abspath(os.path.join(out, "meshes", f"fretting_pad_h{h}_r{ratio}.msh"))
    subprocess.run([sys.executable, os.path.join(MESHES, "fretting_pad.py"), "--h", str(h),
                    "--specimen-h", str(round(ratio * h, 12)), "--out", path], check=True)
    return path


def drive(scene, times):
    """The prescribed x displacement of the pad's top at each instant (piecewise linear)."""
    entry = next(d for d in scene["dirichlet"] if d["boundary"] == "pad_top" and d["component"] == "x")
    return np.interp(times, entry["times"], entry["values"])


def branch_delta(q, delta, at):
    """delta on a branch where Q is monotone, at forces `at`, by linear interpolation."""
    order = np.argsort(q)
    return np.interp(at, q[order], delta[order])


def mindlin_width(q, q_star, mu_p, e_star):
    """delta_u(Q) - delta_l(Q) of the plane-strain loop (docs/two_bodies.md, "Mindlin's loop in 2D")."""
    def g_log_g(g2):
        return 0.5 * g2 * np.log(g2)
    scale = 4.0 * mu_p / (np.pi * e_star)
    return -scale * (g_log_g(1 - (q_star - q) / (2 * mu_p)) + g_log_g(1 - (q_star + q) / (2 * mu_p)) - g_log_g(1 - q_star / mu_p))


def mindlin_area(q_star, mu_p, e_star):
    r = 1.0 - q_star / mu_p
    return 4.0 * mu_p * mu_p / (np.pi * e_star) * (0.5 * (1 - r * r) + r * np.log(r))


def measure(scene, h, ratio, out):
    """The loop on the mesh of spacing h: forces, drive, and its comparison with Mindlin's."""
    sets = [f"mesh.file={mesh_for(h, ratio, out)}"] + (["contact.pairing=segment"] if ratio > 0 else [])
    result = stcontact.solve(SCENE, "incremental", sets=sets, reference=False)
    if not result.converged:
        sys.exit(f"h = {h}: the incremental solve did not converge ({result.termination})")
    m = result.interface_forces.shape[1]
    times = np.linspace(0.0, scene["time"].get("end", 1.0), m)
    q = -result.interface_forces[1::2].sum(axis=0)[PRESS_STEPS:]  # the specimen's force on the pad, against the drive
    p = result.interface_forces[0::2].sum(axis=0)[PRESS_STEPS:]
    delta = drive(scene, times)[PRESS_STEPS:]
    mu = scene["contact"]["friction"]
    young, nu = scene["material"]["young"], scene["material"]["poisson"]
    e_star = young / (2 * (1 - nu * nu))
    P = p.mean()
    q_star, mu_p = q[QUARTER], mu * P
    unload, reload = slice(QUARTER, 3 * QUARTER + 1), slice(3 * QUARTER, 5 * QUARTER + 1)
    grid = np.linspace(-q_star, q_star, 201)
    width = branch_delta(q[unload], delta[unload], grid) - branch_delta(q[reload], delta[reload], grid)
    cycle = slice(QUARTER, 5 * QUARTER + 1)
    area = abs(np.trapz(q[cycle], delta[cycle]))
    a = np.sqrt(4 * P / (np.pi * e_star))  # Hertz's half-width for P, R = 1
    return {"h": h, "a_over_h": a / h, "q_star_over_mu_p": q_star / mu_p, "q": q, "delta": delta, "mu_p": mu_p,
            "grid": grid, "width_curve": width, "mindlin_curve": mindlin_width(grid, q_star, mu_p, e_star),
            "area": area, "area_mindlin": mindlin_area(q_star, mu_p, e_star),
            "width": width[100], "width_mindlin": mindlin_width(0.0, q_star, mu_p, e_star)}


def write_table(runs, out):
    columns = ["h", "a_over_h", "q_star_over_mu_p", "area", "area_mindlin", "area_error", "width", "width_mindlin",
               "width_error"]
    with open(os.path.join(out, "loop.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(columns)
        for r in runs:
            r["area_error"] = r["area"] / r["area_mindlin"] - 1
            r["width_error"] = r["width"] / r["width_mindlin"] - 1
            writer.writerow([f"{r[c]:.6g}" for c in columns])
    print("| h | a/h | Q*/μP | loop area | Mindlin | error | width at Q = 0 | Mindlin | error |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in runs:
        print(f"| {r['h']:g} | {r['a_over_h']:.1f} | {r['q_star_over_mu_p']:.3f} | {r['area']:.4e} | {r['area_mindlin']:.4e} | "
              f"{100 * r['area_error']:+.2f} % | {r['width']:.4e} | {r['width_mindlin']:.4e} | {100 * r['width_error']:+.2f} % |")


def draw(runs, out):
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    for r in runs:
        label = f"h = {r['h']:g} (a/h = {r['a_over_h']:.0f})"
        chord = r["q"] * r["delta"][QUARTER] / r["q"][QUARTER]
        left.plot(1e3 * (r["delta"] - chord), r["q"] / r["mu_p"], label=label)
        right.plot(r["grid"] / r["grid"][-1], 1e3 * r["width_curve"], label=label)
    finest = runs[-1]
    right.plot(finest["grid"] / finest["grid"][-1], 1e3 * finest["mindlin_curve"], "k--", label="Mindlin, plane strain")
    left.set(xlabel="δ − δ* Q/Q* (μm): the drive less the tips' chord", ylabel="Q / μP",
             title="Fretting pad: the loops Q(δ), incremental solver")
    right.set(xlabel="Q / Q*", ylabel="δ_u(Q) − δ_l(Q) (μm)", title="Loop width against the closed form")
    for axes in (left, right):
        axes.grid(alpha=0.3)
        axes.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "loop.png"), dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("Sample run:")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="output folder (created)")
    parser.add_argument("--h", default="0.02,0.01,0.005,0.0025", help="node spacings of the faces")
    parser.add_argument("--specimen-ratio", type=float, default=0.0,
                        help="the specimen's face spacing over h (non-matching faces, node to segment; 0: matching)")
    args = parser.parse_args()
    spacings = [float(v) for v in args.h.split(",")]
    if any(h <= 0 for h in spacings):
        parser.error("--h: node spacings must be positive")
    if args.specimen_ratio < 0:
        parser.error("--specimen-ratio must be >= 0")
    os.makedirs(args.out, exist_ok=True)
    with open(SCENE, "rb") as f:
        scene = tomllib.load(f)
    runs = []
    for h in spacings:
        runs.append(measure(scene, h, args.specimen_ratio, args.out))
        print(f"h = {h:g}: solved", flush=True)
    write_table(runs, args.out)
    draw(runs, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
