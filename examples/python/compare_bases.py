#!/usr/bin/env python3
"""Description: compares the two coarse bases of the FAS on a scene (default: the seed scene,
  examples/scenes/hemicylinder.toml) with the stcontact Python module: the a posteriori basis
  (fas-aposteriori: energy-SVD modes of a converged solution, docs/fas_aposteriori.md) against the
  a priori one (fas-apriori: PGD modes built during the solve, docs/compare_bases.md), and plain
  LATIN as the baseline. Each strategy solves with the incremental reference, so every iteration
  of its history carries the true error. Draws with matplotlib, into the output folder:
    compare_bases.png   true error (solid) and indicator (dotted) against fine LATIN relaxations
  and writes histories.csv (strategy, iteration, relaxations, rank, indicator, error, wall_s).
  Prints, per strategy, the relaxations to reach true errors 1e-4 and 1e-6. Exits with status 1
  when a strategy does not converge.
Sample run:
  PYTHONPATH=build/python /usr/bin/python3 examples/python/compare_bases.py results/compare_bases
  PYTHONPATH=build/python /usr/bin/python3 examples/python/compare_bases.py /tmp/bases \\
      --set mesh.arc_nodes=31 --set time.steps=41 --no-latin
Options: --scene FILE, --tol T (default 1e-8), --set KEY=VALUE (repeatable), --no-latin.
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
STYLES = {"fas-aposteriori": "tab:blue", "fas-apriori": "tab:orange", "latin": "tab:gray"}
TARGETS = (1e-4, 1e-6)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("Sample run:")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="output folder (created)")
    parser.add_argument("--scene", default=SEED_SCENE)
    parser.add_argument("--tol", type=float, default=1e-8, help="tolerance on the error estimate")
    parser.add_argument("--set", dest="sets", action="append", default=[], metavar="KEY=VALUE")
    parser.add_argument("--no-latin", dest="latin", action="store_false", help="leave plain LATIN out")
    return parser.parse_args()


def relaxations_to(result, target):
    """Fine relaxations at the first iteration whose true error is at most `target`, or None."""
    reached = np.nonzero(result.history["error"] <= target)[0]
    return int(result.history["relaxations"][reached[0]]) if reached.size else None


def plot(results, path, scene_name):
    figure, axes = plt.subplots(figsize=(7.5, 4.8))
    for name, result in results.items():
        colour = STYLES[name]
        axes.semilogy(result.history["relaxations"], result.history["error"], color=colour, marker=".",
                      label="%s, true error" % name)
        axes.semilogy(result.history["relaxations"], result.history["indicator"], color=colour, linestyle=":",
                      label="%s, indicator" % name)
    axes.set(xlabel="fine LATIN relaxations", ylabel="relative error / indicator",
             title="A posteriori against a priori basis (%s)" % scene_name)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def write_histories(results, path):
    columns = ["iteration", "relaxations", "rank", "indicator", "error", "wall_s"]
    with open(path, "w", newline="") as f:
        table = csv.writer(f)
        table.writerow(["strategy"] + columns)
        for name, result in results.items():
            for row in zip(*(result.history[c] for c in columns)):
                table.writerow([name] + [value.item() for value in row])


def main():
    args = arguments()
    os.makedirs(args.out, exist_ok=True)
    scene = stcontact.load_scene(args.scene, sets=args.sets)
    solvers = ["fas-aposteriori", "fas-apriori"] + (["latin"] if args.latin else [])
    results = {}
    for solver in solvers:
        results[solver] = result = stcontact.solve(scene, solver, tol=args.tol)
        reached = ", ".join("%g: %s" % (t, relaxations_to(result, t)) for t in TARGETS)
        print("%-16s %s after %d relaxations (rank %d); relaxations to true error %s" % (
            solver, result.termination, result.summary["relaxations"], result.history["rank"][-1], reached),
            flush=True)
    plot(results, os.path.join(args.out, "compare_bases.png"), scene.name)
    write_histories(results, os.path.join(args.out, "histories.csv"))
    print("figure: %s" % os.path.join(args.out, "compare_bases.png"))
    failed = [name for name, result in results.items() if not result.converged]
    if failed:
        print("not converged: %s" % ", ".join(failed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
