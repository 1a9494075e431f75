#!/usr/bin/env bash
# The search-direction study (docs/method.md §2): how many plain-LATIN iterations the seed scene needs for
# each search-direction scale kappa (k_n = k_t = kappa E l_i / L) and relaxation omega, measured both
# with the convergence indicator and with the true error (relative energy error against the
# incremental solver). See docs/search_direction.md.
#
#   scripts/search_direction_study.sh [STCONTACT_BINARY]        # default: build/bin/stcontact
#
# Environment: MAX_IT (iteration cap, default 3000), JOBS (parallel runs, default 2),
#              STC_SD_OUT (scratch folder, default results/search_direction),
#              STC_SD_ANALYZE_ONLY=1 (no runs: redo tables, figure and doc from the runs on disk).
# Phases:
#   1. coarse grids on the seed scene, kappa in {0.01 ... 100} x omega:
#      "ind": --no-reference --tol 1e-6 (iterations to indicator <= 1e-6, the solver's own stop);
#      "err": with the reference, --tol 1e-8, kappa in [0.3, 30] (iterations to true error <= 1e-4
#             and 1e-6, and the true error left when the indicator first reaches 1e-6);
#   2. refinement: kappa in steps of 0.5 around the best kappa (by true error), both grids, every omega;
#   3. scene variants: finer mesh (mesh.arc_nodes=201) and higher friction (contact.friction=0.5),
#      kappa from 1 to 10, at the best omega and at omega = 1, and the next mesh level
#      (mesh.arc_nodes=401) at the best omega for kappa in {3, 4, 5, 7}, all with the reference, to see
#      whether the optimum moves.
# Every run: results/search_direction/runs/<set>/k<kappa>_w<omega>/ (summary.json, history.csv, the
# exact command in "command"). Output: the tables on stdout and in results/search_direction/tables.md,
# the generated section of docs/search_direction.md (between its "search_direction_study" markers)
# and, when gnuplot is installed, docs/figures/search_direction.png. Iteration counts are
# deterministic, so JOBS changes only the wall time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bin=${1:-build/bin/stcontact}
if [[ ! -x $bin ]]; then
  echo "error: stcontact binary '$bin' not found or not executable (build it, or pass its path)" >&2
  exit 1
fi
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
out=${STC_SD_OUT:-$root/results/search_direction}
max_it=${MAX_IT:-3000}
jobs=${JOBS:-2}
scene=examples/scenes/hemicylinder.toml
doc=docs/search_direction.md
figure=docs/figures/search_direction.png
omegas="1.0 0.97 0.95 0.9 0.8 0.6"
coarse_kappas="0.01 0.03 0.1 0.3 1 2 3 4 5 7 10 30 100"
err_kappa_min=0.3   # the true-error grid skips the kappas that need > 1000 iterations anyway
err_kappa_max=30
t_start=$(date +%s.%N)
export bin out max_it scene

# One run. Arguments: set kappa omega reference(0|1) tolerance [section.key=value ...] (overrides).
run_one() {
  local set=$1 kappa=$2 omega=$3 ref=$4 tol=$5
  shift 5
  local dir="$out/runs/$set/k${kappa}_w${omega}"
  rm -rf "$dir"
  mkdir -p "$dir"
  local cmd=("$bin" solve "$scene" --solver latin)
  [[ $ref == 1 ]] || cmd+=(--no-reference)
  cmd+=(--quiet --set output.frames=false)
  local s
  for s in "$@"; do cmd+=(--set "$s"); done
  cmd+=(--set "solver.search_scale=$kappa" --set "solver.relaxation=$omega"
        --tol "$tol" --max-iterations "$max_it" --out "$dir")
  printf '%q ' "${cmd[@]}" >"$dir/command"
  echo >>"$dir/command"
  local rc=0
  "${cmd[@]}" 2>"$dir/stderr.txt" || rc=$?
  echo "$rc" >"$dir/exit_status"
  # 0 converged, 2 not converged (results written); anything else is a failure of the study.
  if [[ $rc != 0 && $rc != 2 ]]; then
    echo "error: run $set kappa=$kappa omega=$omega failed with status $rc: $(head -c 400 "$dir/stderr.txt")" >&2
    return 255  # stops xargs
  fi
  printf '  %-5s kappa=%-5s omega=%-5s status=%s\n' "$set" "$kappa" "$omega" "$rc"
}
export -f run_one

# Runs the job lines read on stdin ("set kappa omega ref tol [overrides...]"), JOBS at a time.
run_jobs() {
  xargs -P "$jobs" -L 1 bash -c 'run_one "$@"' _ || {
    echo "error: some runs failed (see $out/runs/*/*/stderr.txt)" >&2
    exit 3
  }
}

# The analysis (python3): reads every run, chooses the optimum, prints job lines for the next phase
# ("coarse", "refine") or the tables and plot data ("final").
analyze() {
  python3 - "$1" "$out" "$max_it" "$omegas" "$coarse_kappas" "$err_kappa_min" "$err_kappa_max" <<'PY'
import csv, json, math, os, sys
phase, out, max_it = sys.argv[1], sys.argv[2], int(sys.argv[3])
omegas, coarse = sys.argv[4].split(), sys.argv[5].split()
kmin, kmax = float(sys.argv[6]), float(sys.argv[7])
runs = os.path.join(out, "runs")
_cache = {}

def load(set_, kappa, omega):
    key = (set_, kappa, omega)
    if key in _cache:
        return _cache[key]
    d = os.path.join(runs, set_, "k%s_w%s" % (kappa, omega))
    r = None
    if os.path.exists(os.path.join(d, "summary.json")):
        with open(os.path.join(d, "summary.json")) as f:
            s = json.load(f)
        hist = []
        with open(os.path.join(d, "history.csv")) as f:
            for row in csv.DictReader(f):
                hist.append((int(row["iteration"]), float(row["indicator"]),
                             float(row["error"]) if row["error"] else None))
        first = lambda cond: next((h for h in hist if cond(h)), None)
        r = {"converged": s["termination"] == "converged", "iterations": s["iterations"],
             "indicator": s["indicator"], "error": s["error"], "wall_s": s["wall_s"],
             "n_dofs": s["n_dofs"], "n_contact": s["n_contact_nodes"]}
        for name, cond in [("ind4", lambda h: h[1] <= 1e-4), ("ind6", lambda h: h[1] <= 1e-6),
                           ("err4", lambda h: h[2] is not None and h[2] <= 1e-4),
                           ("err6", lambda h: h[2] is not None and h[2] <= 1e-6)]:
            h = first(cond)
            r["it_" + name] = h[0] if h else None
            if name == "ind6":
                r["err_at_ind6"] = h[2] if h else None
    _cache[key] = r
    return r

def kappas_of(set_):
    d = os.path.join(runs, set_)
    return sorted({n[1:].split("_w")[0] for n in os.listdir(d)} if os.path.isdir(d) else set(), key=float)

def its(r, name):
    """Iterations to reach a threshold, or cap + 1 when never reached (for ranking)."""
    if r is None or r["it_" + name] is None:
        return max_it + 1
    return r["it_" + name]

def cell(r, name):
    if r is None:
        return "·"
    v = r["it_" + name]
    return str(v) if v is not None else "> %d" % r["iterations"]

def best_err(set_, omega_list):
    """Best (kappa, omega) by iterations to true error <= 1e-6, then to 1e-4, then smaller kappa."""
    cands = [(its(load(set_, k, w), "err6"), its(load(set_, k, w), "err4"), float(k), k, w)
             for w in omega_list for k in kappas_of(set_) if load(set_, k, w) is not None]
    c = min(cands)
    return c[3], c[4]

def refine_kappas(kbest):
    kb = float(kbest)
    return ["%g" % (kb + 0.5 * j) for j in range(-4, 5) if kb + 0.5 * j > 0.24]

if phase == "coarse":
    kb, wb = best_err("err", omegas)
    for k in refine_kappas(kb):
        if k in coarse:
            continue
        for w in omegas:
            print("ind %s %s 0 1e-6" % (k, w))
            print("err %s %s 1 1e-8" % (k, w))
    sys.exit(0)

if phase == "refine":
    kb, wb = best_err("err", omegas)
    ks = sorted({k for k in coarse if 1 <= float(k) <= 10} | set(refine_kappas(kb)), key=float)
    for w in sorted({wb, "1.0"}, reverse=True):
        for k in ks:
            print("fine %s %s 1 1e-8 mesh.arc_nodes=201" % (k, w))
            print("mu05 %s %s 1 1e-8 contact.friction=0.5" % (k, w))
    for k in ["3", "4", "5", "7"]:
        print("fine401 %s %s 1 1e-8 mesh.arc_nodes=401" % (k, wb))
    sys.exit(0)

# phase == "final": tables, plot data.
kb, wb = best_err("err", omegas)
ki, wi = min((its(load("ind", k, w), "ind6"), float(k), k, w) for w in omegas for k in kappas_of("ind"))[2:]
seed_ks = kappas_of("ind")
lines = []
P = lines.append
def row(k, cells):
    P("| %s | %s |" % (k if k in coarse else "*%s*" % k, " | ".join(cells)))
def header(first, cols):
    P("| %s | %s |" % (first, " | ".join(cols)))
    P("|---:|" + "---:|" * len(cols))

P("Refinement rows (κ in steps of 0.5 around the optimum) are in italics; `> N`: not reached within")
P("the run (cap %d iterations); `·`: not run. Bold: the best cell of the table." % max_it)
P("")
P("#### Table 1. Iterations to indicator ≤ 1e-6 (the solver's stop), seed scene")
P("")
P("`--no-reference --tol 1e-6`. Last two columns: iterations to indicator ≤ 1e-4 at ω = 1.0 and at ω = %s." % wb)
P("")
header("κ", ["ω = %s" % w for w in omegas] + ["to 1e-4, ω = 1.0", "to 1e-4, ω = %s" % wb])
for k in seed_ks:
    cells = [("**%s**" if (k, w) == (ki, wi) else "%s") % cell(load("ind", k, w), "ind6") for w in omegas]
    cells += [cell(load("ind", k, "1.0"), "ind4"), cell(load("ind", k, wb), "ind4")]
    row(k, cells)
P("")
P("#### Table 2. Iterations to TRUE error ≤ 1e-4 / ≤ 1e-6, seed scene")
P("")
P("Same runs with the incremental reference and `--tol 1e-8`; true error = relative elastic energy")
P("error of the full displacement over the time grid (docs/method.md §2).")
P("")
header("κ", ["ω = %s" % w for w in omegas])
for k in seed_ks:
    cells = []
    for w in omegas:
        r = load("err", k, w)
        c = "·" if r is None else "%s / %s" % (cell(r, "err4"), cell(r, "err6"))
        cells.append("**%s**" % c if (k, w) == (kb, wb) else c)
    row(k, cells)
P("")
P("#### Table 3. True error when the indicator first reaches 1e-6 (= at the end of a `--tol 1e-6` run)")
P("")
header("κ", ["ω = %s" % w for w in omegas])
for k in seed_ks:
    cells = []
    for w in omegas:
        r = load("err", k, w)
        cells.append("·" if r is None or r["err_at_ind6"] is None else "%.2g" % r["err_at_ind6"])
    row(k, cells)
P("")
rb, rd, ri = load("err", kb, wb), load("err", "1", "1.0"), load("ind", ki, wi)
P("- Best by true error: **κ = %s, ω = %s**: %s / %s iterations to true error 1e-4 / 1e-6; its `--tol 1e-6`"
  " run stops after %s iterations with true error %.2g (error / indicator ≈ %.0f)."
  % (kb, wb, cell(rb, "err4"), cell(rb, "err6"), cell(rb, "ind6"), rb["err_at_ind6"], rb["err_at_ind6"] / 1e-6))
P("- Best by indicator: κ = %s, ω = %s: %s iterations to indicator 1e-6." % (ki, wi, cell(ri, "ind6")))
if rd is not None:
    P("- Current default κ = 1, ω = 1.0: %s / %s iterations to true error 1e-4 / 1e-6, %s to indicator 1e-6."
      % (cell(rd, "err4"), cell(rd, "err6"), cell(rd, "ind6")))
P("")
P("#### Table 4. Does the optimum move? Iterations to true error ≤ 1e-6 (to indicator ≤ 1e-6)")
P("")
variants = [("err", "seed"), ("fine", "arc_nodes = 201"), ("mu05", "μ = 0.5"), ("fine401", "arc_nodes = 401")]
var_ws = sorted({wb, "1.0"}, reverse=True)
var_ks = sorted(set(kappas_of("fine")) | set(kappas_of("mu05")) | set(kappas_of("fine401")), key=float)
cols = [(s, w) for w in var_ws for s, _ in variants if s != "fine401" or w == wb]
vbest = {}
for s, w in cols:
    c = [(its(load(s, k, w), "err6"), its(load(s, k, w), "err4"), float(k), k) for k in var_ks if load(s, k, w)]
    vbest[(s, w)] = min(c)[3] if c else None
header("κ", ["%s, ω = %s" % (dict(variants)[s], w) for s, w in cols])
for k in var_ks:
    cells = []
    for s, w in cols:
        r = load(s, k, w)
        c = "·" if r is None else "%s (%s)" % (cell(r, "err6"), cell(r, "ind6"))
        cells.append("**%s**" % c if k == vbest[(s, w)] else c)
    row(k, cells)
P("")
sizes = {s: next((load(s, k, w) for w in var_ws for k in var_ks if load(s, k, w)), None) for s, _ in variants}
P("Best κ by true error: " + "; ".join("%s, ω = %s: κ = %s" % (dict(variants)[s], w, vbest[(s, w)]) for s, w in cols)
  + ". Sizes: " + ", ".join("%s %d dofs / %d contact nodes" % (dict(variants)[s], sizes[s]["n_dofs"], sizes[s]["n_contact"])
                            for s, _ in variants if sizes[s]) + ".")
P("")
# Robustness at the best omega: for each kappa run on every scene, the worst ratio of its iterations to
# the scene's best (true error 1e-6); the minimax kappa is the safest single default.
scen = [s for s, _ in variants if vbest.get((s, wb))]
common = [k for k in var_ks if all(load(s, k, wb) and load(s, k, wb)["it_err6"] for s in scen)]
best_of = {s: its(load(s, vbest[(s, wb)], wb), "err6") for s in scen}
worst = {k: max(its(load(s, k, wb), "err6") / best_of[s] for s in scen) for k in common}
krob = min(common, key=lambda k: (worst[k], float(k))) if common else kb
P("#### Table 5. Robustness at ω = %s: iterations to true error 1e-6 / the scene's best" % wb)
P("")
header("κ", [dict(variants)[s] for s in scen] + ["worst"])
for k in common:
    cells = ["%.2f" % (its(load(s, k, wb), "err6") / best_of[s]) for s in scen]
    c = "%.2f" % worst[k]
    row(k, cells + ["**%s**" % c if k == krob else c])
P("")
P("Minimax κ over these scenes at ω = %s: **κ = %s** (at most %.0f%% more iterations than each scene's own optimum)."
  % (wb, krob, 100 * (worst[krob] - 1)) if common else "")
table = "\n".join(lines)
print(table)
with open(os.path.join(out, "tables.md"), "w") as f:
    f.write(table + "\n")
with open(os.path.join(out, "best.txt"), "w") as f:
    f.write("%s %s %s\n" % (kb, wb, krob))

# Plot data: iterations against kappa, NaN when not reached or not run.
def num(r, name):
    return str(r["it_" + name]) if r is not None and r["it_" + name] is not None else "NaN"
with open(os.path.join(out, "plot_seed.dat"), "w") as f:
    f.write("# kappa, then per omega in (%s): iterations to indicator 1e-6, to true error 1e-6\n" % " ".join(omegas))
    for k in seed_ks:
        f.write(k + " " + " ".join("%s %s" % (num(load("ind", k, w), "ind6"), num(load("err", k, w), "err6"))
                                   for w in omegas) + "\n")
# The right panel's plot command (a gnuplot include): one inline data block per scene and omega,
# dashed at omega = 1, solid at the best omega, one colour per scene.
with open(os.path.join(out, "plot_variants.gp"), "w") as f:
    series = [(s, w) for s, w in cols if any(load(s, k, w) and load(s, k, w)["it_err6"] for k in var_ks)]
    color = {s: i + 1 for i, (s, _) in enumerate(variants)}
    f.write("plot " + ", \\\n     ".join(
        "'-' using 1:2 with linespoints lw 2 dt %d pt 7 ps 0.5 lc %d title '%s, omega = %s'"
        % (2 if w == "1.0" and wb != "1.0" else 1, color[s], dict(variants)[s].replace("μ", "mu"), w)
        for s, w in series) + "\n")
    for s, w in series:
        for k in var_ks:
            r = load(s, k, w)
            if r and r["it_err6"]:
                f.write("%s %d\n" % (k, r["it_err6"]))
        f.write("e\n")
PY
}

if [[ ${STC_SD_ANALYZE_ONLY:-0} != 1 ]]; then
rm -rf "$out/runs"  # a clean slate: the analysis reads every run it finds
mkdir -p "$out/runs"
echo "== 1. coarse grids on the seed scene (cap $max_it iterations)"
for w in $omegas; do
  for k in $coarse_kappas; do
    echo "ind $k $w 0 1e-6"
    if python3 -c "import sys; sys.exit(not ($err_kappa_min <= $k <= $err_kappa_max))"; then
      echo "err $k $w 1 1e-8"
    fi
  done
done | run_jobs

echo "== 2. refinement around the optimum"
analyze coarse | run_jobs

echo "== 3. scene variants (arc_nodes=201 and 401, friction=0.5)"
analyze refine | run_jobs
python3 -c "print('%.0f' % ($(date +%s.%N) - $t_start))" >"$out/wall_runs_s.txt"
fi

echo "== 4. tables"
tables=$(analyze final)
read -r kbest wbest krobust <"$out/best.txt"
if command -v gnuplot >/dev/null; then
  mkdir -p "$(dirname "$figure")"
  gnuplot -e "data='$out'; out='$figure'; omegas='$omegas'; wbest='$wbest'" scripts/plots/search_direction.gp
  echo "figure: $figure"
fi
t_end=$(date +%s.%N)
wall=$(python3 -c "print('%.0f' % ($t_end - $t_start + float(open('$out/wall_runs_s.txt').read()) * ${STC_SD_ANALYZE_ONLY:-0}))")
nruns=$(find "$out/runs" -name summary.json | wc -l)
version=$("$bin" --version 2>&1 | head -1)
echo "$tables"
echo
echo "best by true error on the seed scene: kappa=$kbest omega=$wbest; minimax over the scenes: kappa=$krobust; $nruns runs, study wall time ${wall} s ($jobs runs at a time)"

# The generated section of docs/search_direction.md (between the markers; the rest is prose).
python3 - "$doc" "$out/tables.md" "$wall" "$jobs" "$max_it" "$version" "$(nproc)" "$nruns" <<'PY'
import os, sys
doc, tables, wall, jobs, max_it, version, ncpu, nruns = sys.argv[1:]
begin = "<!-- search_direction_study: begin (generated by scripts/search_direction_study.sh, do not edit) -->"
end = "<!-- search_direction_study: end -->"
with open(tables) as f:
    body = f.read().rstrip("\n")
section = "\n".join([
    begin, "",
    "Generated by `scripts/search_direction_study.sh` with `%s`: %s runs of plain LATIN, iteration"
    " cap %s, %s s wall time for the whole study (%s runs at a time on %s cores)."
    % (version, nruns, max_it, wall, jobs, ncpu),
    "", body, "", end])
text = open(doc).read() if os.path.exists(doc) else "# Search direction study\n"
if begin in text and end in text:
    text = text[:text.index(begin)] + section + text[text.index(end) + len(end):]
else:
    text = text.rstrip("\n") + "\n\n" + section + "\n"
with open(doc + ".tmp", "w") as f:
    f.write(text)
os.replace(doc + ".tmp", doc)
PY
echo "wrote $doc (generated section), $out/tables.md"
