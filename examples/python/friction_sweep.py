#!/usr/bin/env python3
"""Description: sweeps the Coulomb coefficient of the seed scene (examples/scenes/hemicylinder.toml,
  contact.friction over 0.05 ... 0.5) with the stcontact Python module. Each solve starts from the
  previous value's solution (its interface histories and, for fas-apriori and latin-pgd, its spatial
  modes: a warm start); each value is also solved from zero (cold) for comparison. Draws with
  matplotlib, into the output folder:
    reactions.png      normal and tangential reaction against time, one curve per value
    error_vs_time.png  true error against wall time of every solve, warm (solid) and cold (dashed)
  and writes sweep.csv (one row per value: relaxations and seconds warm and cold, final reactions).
  Exits with status 1 when a solve does not converge.
Sample run:
  PYTHONPATH=build/python /usr/bin/python3 examples/python/friction_sweep.py results/friction_sweep
  PYTHONPATH=build/python /usr/bin/python3 examples/python/friction_sweep.py /tmp/sweep \\
      --set mesh.arc_nodes=31 --set time.steps=41 --values 0.05:0.5:4
Options: --scene FILE, --solver NAME (default fas-apriori), --values LIST (comma-separated, or
  START:STOP:COUNT; default 0.05:0.5:10), --set KEY=VALUE (repeatable), --no-cold.
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
SEED_SCENE = os.path.join(HERE, "..", "scenes", "hemicylinder.toml")


def friction_values(text):
    """'0.05,0.1' or '0.05:0.5:10' (START:STOP:COUNT, both ends included)."""
    if ":" in text:
        start, stop, count = text.split(":")
        return [round(v, 10) for v in np.linspace(float(start), float(stop), int(count))]
    return [float(v) for v in text.split(",")]


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("Sample run:")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="output folder (created)")
    parser.add_argument("--scene", default=SEED_SCENE)
    parser.add_argument("--solver", default="fas-apriori")
    parser.add_argument("--values", type=friction_values, default=friction_values("0.05:0.5:10"))
    parser.add_argument("--set", dest="sets", action="append", default=[], metavar="KEY=VALUE")
    parser.add_argument("--no-cold", dest="cold", action="store_false", help="solve warm only")
    return parser.parse_args()


def sweep(scene, solver, values, cold):
    """[(mu, warm result, cold result or None)], each warm solve starting from the previous one."""
    runs, previous = [], None
    for mu in values:
        at_mu = scene.with_sets({"contact.friction": mu})
        warm = stcontact.solve(at_mu, solver, start=previous)
        from_zero = stcontact.solve(at_mu, solver) if cold and previous is not None else None
        runs.append((mu, warm, from_zero))
        previous = warm
        line = "mu = %-5g warm: %s, %d relaxations, %.2f s" % (mu, warm.termination, warm.summary["relaxations"],
                                                                 warm.summary["wall_s"])
        if from_zero is not None:
            line += "; cold: %d relaxations, %.2f s" % (from_zero.summary["relaxations"], from_zero.summary["wall_s"])
        print(line, flush=True)
    return runs


def plot_reactions(runs, path):
    figure, (normal, tangential) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(runs)))
    for (mu, warm, _), colour in zip(runs, colours):
        normal.plot(warm.reactions["t"], warm.reactions["normal_force"], color=colour, label="μ = %g" % mu)
        tangential.plot(warm.reactions["t"], warm.reactions["tangential_force"], color=colour)
    normal.set(xlabel="time t", ylabel="normal reaction (N/mm)", title="Normal contact force")
    tangential.set(xlabel="time t", ylabel="tangential reaction (N/mm)", title="Tangential contact force")
    normal.legend(fontsize=7, ncol=2)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def plot_errors(runs, path):
    figure, axes = plt.subplots(figsize=(7, 4.5))
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(runs)))
    for (mu, warm, cold), colour in zip(runs, colours):
        axes.semilogy(warm.history["wall_s"], warm.history["error"], color=colour, label="μ = %g" % mu)
        if cold is not None:
            axes.semilogy(cold.history["wall_s"], cold.history["error"], color=colour, linestyle="--")
    axes.set(xlabel="wall time of the solve (s)", ylabel="true error (relative energy)",
             title="True error against time: warm start (solid), from zero (dashed)")
    axes.legend(fontsize=7, ncol=2)
    axes.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def write_table(runs, path):
    with open(path, "w", newline="") as f:
        table = csv.writer(f)
        table.writerow(["friction", "warm_relaxations", "warm_s", "cold_relaxations", "cold_s", "warm_error",
                        "final_normal_force", "final_tangential_force"])
        for mu, warm, cold in runs:
            table.writerow([mu, warm.summary["relaxations"], warm.summary["wall_s"],
                            cold.summary["relaxations"] if cold else "", cold.summary["wall_s"] if cold else "",
                            warm.error, warm.reactions["normal_force"][-1], warm.reactions["tangential_force"][-1]])


def main():
    args = arguments()
    os.makedirs(args.out, exist_ok=True)
    scene = stcontact.load_scene(args.scene, sets=args.sets)
    runs = sweep(scene, args.solver, args.values, args.cold)
    plot_reactions(runs, os.path.join(args.out, "reactions.png"))
    plot_errors(runs, os.path.join(args.out, "error_vs_time.png"))
    write_table(runs, os.path.join(args.out, "sweep.csv"))
    print("figures: %s, %s" % (os.path.join(args.out, "reactions.png"), os.path.join(args.out, "error_vs_time.png")))
    failed = [mu for mu, warm, cold in runs if not warm.converged or (cold is not None and not cold.converged)]
    if failed:
        print("not converged for friction %s" % ", ".join("%g" % mu for mu in failed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
