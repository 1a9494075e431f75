"""Python under MPI (docs/python.md, "On several MPI ranks"): `mpirun -np 2 python3 script.py` solves
as `mpirun -np 2 stcontact solve` does (tests/cli/mpi_ranks.sh checks the program).

    python3 mpi_ranks.py WORK          the check: runs this file as a script on 1 process and on 2 ranks
    python3 mpi_ranks.py --rank WORK   what each rank runs (under mpirun, or alone as the one process)

Checked, on the seed scene (small settings):
- ranks() says (r, 2) on rank r, (0, 1) alone;
- with mumps, every rank returns the reactions of one process to 1e-8 relative (round-off apart) and
  the same iterations, its summary says 2 ranks, one peak per rank;
- with cg-gamg and the incremental reference the ranks compute together, converged with its true
  error within the tolerance;
- rank 0 alone writes `out` (each rank passes its own folder: only rank 0's exists, complete);
- cholmod, threads=2 and svd() are refused on 2 ranks with their messages, on every rank.
Exit 0 when every check held; each failure is printed.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

SOURCE_DIR = Path(os.environ.get("STC_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SEED = str(SOURCE_DIR / "examples" / "scenes" / "hemicylinder.toml")
SMALL = ["mesh.arc_nodes=31", "time.steps=31", "output.frames=false"]
TOL = 1e-6


def refused(call, words):
    """The message of the InputError `call` raised, which must contain `words`; None if it did not."""
    import stcontact
    try:
        call()
    except stcontact.InputError as e:
        return str(e) if words in str(e) else "wrong message: " + str(e)
    return None


def on_rank(work):
    """Each rank's part: its solves, written as rank_<size>_<rank>.json in `work`."""
    import stcontact
    rank, size = stcontact.ranks()
    mumps = stcontact.solve(SEED, sets=SMALL + ['solver.linear="mumps"'], tol=TOL, reference=False,
                            out=work / f"out_{size}_{rank}")
    gamg = stcontact.solve(SEED, sets=SMALL + ['solver.linear="cg-gamg"'], tol=TOL)
    report = {
        "ranks": [rank, size],
        "mumps": {"normal_force": list(mumps.reactions["normal_force"]),
                  "tangential_force": list(mumps.reactions["tangential_force"]),
                  "iterations": mumps.summary["iterations"], "summary_ranks": mumps.summary["ranks"],
                  "peaks": mumps.summary["peak_memory_bytes_per_rank"]},
        "gamg": {"termination": gamg.summary["termination"], "error": gamg.summary["error"],
                 "summary_ranks": gamg.summary["ranks"]},
    }
    if size > 1:
        report["refusals"] = {
            "cholmod": refused(lambda: stcontact.solve(SEED, sets=SMALL + ['solver.linear="cholmod"'], reference=False),
                               "runs in one process; on 2 ranks choose"),
            "threads": refused(lambda: stcontact.solve(SEED, sets=SMALL, threads=2, reference=False),
                               "each rank runs one thread"),
            "svd": refused(lambda: stcontact.svd(SEED, sets=SMALL), "svd runs in one process"),
        }
    (work / f"rank_{size}_{rank}.json").write_text(json.dumps(report))


def run(command, env):
    done = subprocess.run(command, env=env, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        print(f"FAIL: {' '.join(command)}: exit {done.returncode}\n{done.stdout}{done.stderr}")
    return done.returncode == 0


def check(work):
    work.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_plm="isolated",
               OMPI_MCA_btl_vader_single_copy_mechanism="none")
    me = [sys.executable, __file__, "--rank", str(work)]
    if not (run(me, env) and run(["mpirun", "-np", "2", "--oversubscribe", *me], env)):
        return 1
    one = json.loads((work / "rank_1_0.json").read_text())
    failures = []

    def expect(cond, what):
        if not cond:
            failures.append(what)

    expect(one["ranks"] == [0, 1], f"alone: ranks() {one['ranks']}")
    for rank in (0, 1):
        two = json.loads((work / f"rank_2_{rank}.json").read_text())
        at = f"rank {rank} of 2"
        expect(two["ranks"] == [rank, 2], f"{at}: ranks() {two['ranks']}")
        m1, m2 = one["mumps"], two["mumps"]
        expect(m2["summary_ranks"] == 2 and len(m2["peaks"]) == 2, f"{at}: summary ranks {m2['summary_ranks']}")
        expect(abs(m1["iterations"] - m2["iterations"]) <= 1, f"{at}: iterations {m2['iterations']} against {m1['iterations']}")
        scale = max(abs(x) for x in m1["normal_force"] + m1["tangential_force"])
        worst = max(abs(a - b) for key in ("normal_force", "tangential_force") for a, b in zip(m1[key], m2[key]))
        expect(worst <= 1e-8 * scale, f"{at}: reactions differ by {worst:.3g} of {scale:.3g}")
        g = two["gamg"]
        expect(g["termination"] == "converged" and g["error"] is not None and g["error"] <= TOL,
               f"{at}: cg-gamg {g['termination']}, true error {g['error']}")
        for what, message in two["refusals"].items():
            expect(message is not None and not message.startswith("wrong message"), f"{at}: {what}: {message}")
    written = json.loads((work / "out_2_0" / "summary.json").read_text())
    expect(written["ranks"] == 2, f"out_2_0 says {written['ranks']} ranks")
    expect(not (work / "out_2_1").exists(), "rank 1 wrote its out folder")
    for f in failures:
        print("FAIL: " + f)
    print("every check held" if not failures else f"{len(failures)} failures")
    return 0 if not failures else 1


if __name__ == "__main__":
    if sys.argv[1] == "--rank":
        on_rank(Path(sys.argv[2]))
    else:
        sys.exit(check(Path(sys.argv[1])))
