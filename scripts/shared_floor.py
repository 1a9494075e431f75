#!/usr/bin/python3
"""What bounds fas-apriori's lead over incremental: the parts of a solve that the iterations cannot cut.

For each scene, a solve at tolerance tau as `stcontact solve --tol tau` makes it (it stops on its own
estimate), fas-apriori and incremental alternated, REPEATS times each, medians. Each solve's time is
split with its own history.csv (wall_s since the solver was called, one row per iteration):

  fas-apriori   set-up   = wall_s of its first row (factorisation, contact zone, its first
                           relaxation) less the sub-grid solve of long grids (summary.json's sub_grid);
                iterations = last row - first row, and that sub-grid solve;
                lift     = the whole solve - last row: the displacements of the contact nodes left
                           out of the zone (a sparse solve per rank of the zone's force history);
  incremental   set-up   = wall_s of its first row (factorisation and the zone's Delassus operator);
                instants = last row - first row; lift = the whole solve - last row.

The lead is incremental's whole solve over fas-apriori's (above 1: fas-apriori is faster); its
ceiling is incremental's whole solve over fas-apriori's set-up and lift: the ratio fas-apriori
would reach if every relaxation after its first cost nothing. A goal above it cannot be met by
fewer or cheaper relaxations. Prints a Markdown table.

    /usr/bin/python3 scripts/shared_floor.py [REPEATS] [--large]

--large adds the hemisphere at divisions 16 (its incremental solve alone takes about 9 s here).
STC_BIN names the program (default build/bin/stcontact).
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # study_scenes.py, also when loaded by path
from study_scenes import (ARC_NODES_801, ARC_NODES_1601, FRETTING, HEMISPHERE_8, HEMISPHERE_12,
                          HEMISPHERE_16, LONG_GRID, SEED_SCENE)

SCENES = [SEED_SCENE, ARC_NODES_801, ARC_NODES_1601, LONG_GRID, FRETTING, HEMISPHERE_8, HEMISPHERE_12]
LARGE = [HEMISPHERE_16]
SOLVERS = ("fas-apriori", "incremental")
TOLERANCE = 1e-6


def timed_solve(binary, scene, sets, solver, out):
    """One solve at TOLERANCE; returns (set-up, iterations, lift, whole) in seconds from its outputs."""
    command = [binary, "solve", scene, "--solver", solver, "--tol", str(TOLERANCE), "--no-reference",
               "--set", "output.frames=false", "--out", out]
    for item in sets:
        command += ["--set", item]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    if summary["termination"] != "converged":
        raise RuntimeError(f"{solver} on {scene} {sets}: {summary['termination']}: {summary['message']}")
    with open(os.path.join(out, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    first, last, whole = float(rows[0]["wall_s"]), float(rows[-1]["wall_s"]), float(summary["wall_s"])
    sub_grid = summary["sub_grid"]["wall_s"] if summary.get("sub_grid") else 0.0
    return first - sub_grid, last - first + sub_grid, whole - last, whole


def measure(binary, scene, sets, repeats, workdir):
    """Medians of each part per solver, the runs alternated by solver."""
    parts = {solver: [] for solver in SOLVERS}
    for _ in range(repeats):
        for solver in SOLVERS:
            parts[solver].append(timed_solve(binary, scene, sets, solver, os.path.join(workdir, solver)))
    return {solver: [statistics.median(column) for column in zip(*runs)] for solver, runs in parts.items()}


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 and sys.argv[1].isdigit() else 3
    scenes = SCENES + (LARGE if "--large" in sys.argv else [])
    binary = os.environ.get("STC_BIN", "build/bin/stcontact")
    print(f"Solves at tolerance {TOLERANCE}, medians of {repeats}, seconds.\n")
    print("| scene | fas-apriori: set-up | iterations | lift | whole | incremental: set-up | instants | lift "
          "| whole | lead | ceiling of the lead |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as workdir:
        for label, scene, sets in scenes:
            m = measure(binary, scene, sets, repeats, workdir)
            fas, inc = m["fas-apriori"], m["incremental"]
            cells = " | ".join(f"{value:.3g}" for value in fas + inc)
            print(f"| {label} | {cells} | {inc[3] / fas[3]:.2f} | {inc[3] / (fas[0] + fas[2]):.2f} |", flush=True)


if __name__ == "__main__":
    main()
