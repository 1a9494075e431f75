#!/usr/bin/env python3
"""A scaling model to 10^3 ranks: the space-time solver (fas-apriori) against the incremental one
on P MPI ranks with CG + GAMG, for a body of n dofs with n_C contact nodes and m instants
(docs/scale.md, "A scaling model to 10³ ranks", which derives each term).

    one sparse solve on q ranks      t_s(n, q) = t_1(n) / (min(q, n / n_min) e) + k(n) c α log2 q
    incremental (sequential in time) T_inc(P) = N_N · t_s'(n, P)           (one solve per Newton step)
    space-time  (R relaxations)      T_st(P)  = Σ_relax ⌈r / g⌉ t_s"(n, P / g)  (r new directions,
                                               solved concurrently by g groups of P / g ranks)
                                               + R (w d z m / P + c_r α log2 P)   (z: zone nodes)

t_1(n) and k(n) (one rank's time and Krylov iterations per right-hand side) are power laws fitted
to the measured table of docs/linear_solvers.md ("The crossover", "A million degrees of freedom");
e is the measured efficiency of two ranks on one machine; R, r = S / R and a direction's Krylov
iterations (t_s") are power laws fitted to fas-apriori's measured solves of the fretting history on
CG + GAMG (FRETTING_CG below), N_N and a Newton step's Krylov iterations (t_s') the incremental
solver's whole-body form measured on the same history (docs/scale.md); α, c, c_r and n_min (the fewest dofs per rank with which
a sparse solve still gains from another rank) are assumptions about a cluster and an AMG, given as
options. Prints Markdown tables: the model against the measured one- and
two-rank points, then T(P) and the saturation rank counts at 10^6 and 10^7 dofs.

    python3 scripts/scaling_model.py
    python3 scripts/scaling_model.py --latency 1e-5     # a slower interconnect
"""
import argparse
import math

# One rank, CG + GAMG to 1e-10, per right-hand side: (free dofs, seconds, Krylov iterations).
# build/bin/linear_backends_study --sizes 8,12,16,20 --rhs 8 --repeats 3; --sizes 30 ...; --sizes 44
# --rhs 4 --backends cg-gamg (docs/linear_solvers.md).
ONE_RANK = [(6936, 0.0145, 18.8), (22500, 0.105, 22.0), (52272, 0.38, 24.6), (100860, 0.927, 26.0),
            (334890, 3.68, 30.0), (1045572, 11.8, 34.0)]
# Two ranks, the same runs under mpirun -np 2: (free dofs, seconds per right-hand side).
TWO_RANKS = [(6936, 0.00842), (22500, 0.047), (52272, 0.248), (100860, 0.498), (334890, 2.03),
             (1045572, 7.86)]

# fas-apriori on the fretting history (2001 instants), CG + GAMG on two ranks, τ = 1e-6, no reference,
# without nested iteration in time (its default on an iterative backend): (dofs, relaxations, sparse
# solves, Krylov iterations) of summary.json, divisions 8, 12, 16, 20, 30:
#   mpirun -np 2 stcontact solve examples/scenes/hemisphere_fretting.toml --set mesh.divisions=D \
#     --set 'solver.linear="cg-gamg"' --tol 1e-6 --no-reference --set output.frames=false --threads 1
FRETTING_CG = [(7803, 18, 80, 1603), (24375, 27, 172, 3419), (55539, 35, 306, 6039), (105903, 43, 471, 9514),
               (346053, 61, 1497, 26260)]


def power_fit(points):
    """(a, b) of y = a x^b by least squares on log-log axes."""
    xs = [math.log(x) for x, _ in points]
    ys = [math.log(y) for _, y in points]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return math.exp(my - b * mx), b


class Model:
    def __init__(self, args):
        self.t1 = power_fit([(n, t) for n, t, _ in ONE_RANK])
        self.k = power_fit([(n, k) for n, _, k in ONE_RANK])
        self.solves = power_fit([(n, solves) for n, _, solves, _ in FRETTING_CG])
        self.relaxations = power_fit([(n, r) for n, r, _, _ in FRETTING_CG])
        self.direction_krylov = power_fit([(n, its / solves) for n, _, solves, its in FRETTING_CG])
        speedups = [t / t2 for (n, t, _), (_, t2) in zip(ONE_RANK, TWO_RANKS)]
        self.efficiency = sum(speedups) / len(speedups) / 2.0  # of two ranks sharing one machine
        self.alpha, self.messages, self.reductions = args.latency, args.messages, args.reductions
        self.local_work, self.newton_krylov = args.local_work, args.newton_krylov
        self.min_dofs = args.min_dofs_per_rank

    def t_1(self, n):
        return self.fitted(self.t1, n)

    def krylov(self, n):
        return self.fitted(self.k, n)

    def latency(self, q):
        return self.alpha * math.log2(q) if q > 1 else 0.0

    def solve(self, n, q, krylov_share=1.0):
        """t_s(n, q): one right-hand side on q ranks, krylov_share of a cold solve's iterations."""
        eff = 1.0 if q == 1 else self.efficiency
        working = max(1.0, min(q, n / self.min_dofs))  # ranks beyond n / n_min add messages, not speed
        return krylov_share * (self.t_1(n) / (working * eff) + self.krylov(n) * self.messages * self.latency(q))

    @staticmethod
    def fitted(fit, n):
        """a n^b of a power_fit's (a, b)."""
        return fit[0] * n ** fit[1]

    def direction_share(self, n):
        """A direction's Krylov iterations over a cold solve's (t_s"/t_s), at most 1."""
        return min(1.0, self.fitted(self.direction_krylov, n) / self.krylov(n))

    def incremental(self, n, P, newton):
        """Newton steps in sequence, each one warm-started solve of the whole body on P ranks."""
        return newton * self.solve(n, P, self.newton_krylov)

    def space_time(self, n, n_c, m, P, relaxations, solves):
        """Best split of P ranks into g groups solving a relaxation's new directions concurrently."""
        per_relaxation = solves / relaxations
        best = math.inf
        g = 1
        while g <= P:
            solves_time = (relaxations * math.ceil(per_relaxation / g)
                           * self.solve(n, max(1, P // g), self.direction_share(n)))
            best = min(best, solves_time)
            g *= 2
        local = relaxations * (self.local_work * 3 * n_c * m / P + self.reductions * self.latency(P))
        return best + local


def check_runs(folder, solve_times=None):
    """The model of today's code (the solves split over the ranks, the rest replicated) against the
    one- and two-rank cg-gamg solves in `folder` (<solver>-cg-gamg-np1, -np2: summary.json each).
    `solve_times`: (t_s(1), t_s(2), Krylov iterations per solve) measured the same day at that size,
    in place of the table's (this machine's CG + GAMG solves vary by up to 2.7 times between days)."""
    import json
    import os
    print("\nWhole solves on CG + GAMG, one rank against two (today's code: the solves split, the rest "
          "replicated); predicted T(2) = preparation(1) / 2 + S t_s(2) + rest(1):\n")
    print("| solver | T(1) s | solves | rest(1) s | T(2) predicted s | T(2) measured s |")
    print("|---|---:|---:|---:|---:|---:|")
    for solver in ("incremental", "fas-apriori"):
        runs = {}
        for ranks in (1, 2):
            with open(os.path.join(folder, "%s-cg-gamg-np%d" % (solver, ranks), "summary.json")) as f:
                runs[ranks] = json.load(f)
        one = runs[1]
        free = next(n for n, _, _ in ONE_RANK if n >= one["n_dofs"] * 0.9)
        t1, k1 = next((t, k) for n, t, k in ONE_RANK if n == free)
        t2 = next(t for n, t in TWO_RANKS if n == free)
        if solve_times:
            t1, t2, k1 = solve_times
        solves = one["sparse_solves"]
        share = one["krylov_iterations"] / max(1, solves) / k1  # its Krylov iterations per solve over the table's
        prep = sum(p["seconds"] for p in one["preparations"])
        rest = one["wall_s"] - prep - solves * t1 * share
        predicted = prep / 2 + solves * t2 * share + rest
        print("| %s | %.3g | %d | %.3g | %.3g | %.3g |" % (solver, one["wall_s"], solves, rest, predicted,
                                                          runs[2]["wall_s"]))


def saturation(times, ranks):
    """The first rank count whose doubling gains less than 10 %, or the last one."""
    for (p, t), (_, t2) in zip(zip(ranks, times), zip(ranks[1:], times[1:])):
        if t2 > 0.9 * t:
            return p
    return ranks[-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--latency", type=float, default=2e-6,
                        help="α: seconds per tree level of a global reduction (assumed, an InfiniBand-class network)")
    parser.add_argument("--messages", type=float, default=10.0,
                        help="c: latency-bound messages per Krylov iteration (two dot products and the halo "
                             "exchanges of an AMG V-cycle's levels; assumed)")
    parser.add_argument("--reductions", type=float, default=20.0,
                        help="c_r: global reductions per relaxation (Gram matrices, coarse problem, indicator; assumed)")
    parser.add_argument("--local-work", type=float, default=None,
                        help="w: seconds per zone row-instant of a relaxation's work beside its solves "
                             "(default: measured, --measured-relaxation)")
    parser.add_argument("--measured-relaxation", type=float, nargs=4, metavar=("ZONE", "M", "R", "REST_S"),
                        default=[109, 2001, 20, 2.56],
                        help="a measured fas-apriori solve: the contact zone's nodes, instants, relaxations and its "
                             "time beside the sparse solves and the preparation (docs/scale.md: the fretting "
                             "history at divisions 12, one thread, 4.29 s - 1.38 s preparing - 98 solves x 3.6 ms)")
    parser.add_argument("--zone-fraction", type=float, default=0.065,
                        help="the contact zone's share of the contact nodes (measured: 109 of 1681, 197 of 3009)")
    parser.add_argument("--min-dofs-per-rank", type=float, default=1e4,
                        help="n_min: the fewest dofs per rank with which a CG + GAMG solve still gains from "
                             "another rank (assumed)")
    parser.add_argument("--newton-krylov", type=float, default=0.89,
                        help="a Newton step's Krylov iterations over a cold solve's (measured: the whole-body "
                             "form on the fretting history at divisions 8, 19.5 against 22.0, docs/scale.md)")
    parser.add_argument("--newton-per-instant", type=float, default=1.31,
                        help="Newton steps (warm sparse solves) per instant of the incremental solver (measured: "
                             "the whole-body form, 2628 over 2001 instants at divisions 8, docs/scale.md)")
    parser.add_argument("--solves", type=float, default=None,
                        help="S, the space-time solver's sparse solves at 10^6 dofs, grown at the fitted "
                             "exponent past it (default: the fit to FRETTING_CG)")
    parser.add_argument("--relaxations", type=float, default=None,
                        help="R at 10^6 dofs, grown at the fitted exponent (default: the fit to FRETTING_CG)")
    parser.add_argument("--instants", type=int, default=2001)
    parser.add_argument("--check", metavar="DIR",
                        help="the folder of the one- and two-rank solves to check the model against (docs/scale.md)")
    parser.add_argument("--check-solve-times", type=float, nargs=3, metavar=("T1", "T2", "KRYLOV"),
                        help="with --check: seconds per right-hand side on one rank and on two, and Krylov "
                             "iterations per right-hand side on one, measured the same day at the checked size "
                             "(linear_backends_study --backends cg-gamg), in place of the fitted table's")
    args = parser.parse_args()
    zone, m, relaxations, rest_s = args.measured_relaxation
    if args.local_work is None:
        args.local_work = rest_s / (relaxations * 3 * zone * m)
    model = Model(args)

    print("Fits: t_1(n) = %.3g n^%.3f s, k(n) = %.3g n^%.3f; two ranks on this machine: efficiency %.2f; "
          "w = %.3g s per zone row-instant\n" % (model.t1[0], model.t1[1], model.k[0], model.k[1],
                                                      model.efficiency, args.local_work))
    print("fas-apriori on CG + GAMG (FRETTING_CG): S(n) = %.3g n^%.3f solves, R(n) = %.3g n^%.3f relaxations, "
          "%.3g n^%.3f Krylov iterations per direction (%.2f of a cold solve's at 10^6 dofs)\n"
          % (*model.solves, *model.relaxations, *model.direction_krylov, model.direction_share(1e6)))
    print("Sparse solves on one and two ranks, measured and modelled (seconds per right-hand side):\n")
    print("| free dofs | one rank measured s | model | two ranks measured s | model |")
    print("|---:|---:|---:|---:|---:|")
    for (n, t, _), (_, t2) in zip(ONE_RANK, TWO_RANKS):
        print("| %d | %.3g | %.3g | %.3g | %.3g |" % (n, t, model.solve(n, 1), t2, model.solve(n, 2)))

    if args.check:
        check_runs(args.check, args.check_solve_times)

    ranks = [2 ** i for i in range(0, 15)]
    for n in (1e6, 1e7):
        zone_n = args.zone_fraction * 23057 * (n / 1.045e6) ** (2.0 / 3.0)  # contact nodes grow as n^(2/3)
        newton = args.newton_per_instant * args.instants
        solves, relaxations = model.fitted(model.solves, n), model.fitted(model.relaxations, n)
        if args.solves is not None:
            solves = args.solves * (n / 1e6) ** model.solves[1]
        if args.relaxations is not None:
            relaxations = args.relaxations * (n / 1e6) ** model.relaxations[1]
        solves = min(solves, 3 * zone_n)  # at most a direction per zone row (the responses' basis is full)
        inc = [model.incremental(n, P, newton) for P in ranks]
        st = [model.space_time(n, zone_n, args.instants, P, relaxations, solves) for P in ranks]
        print("\n%.0e dofs, a zone of %d contact nodes, %d instants: %d Newton steps in sequence against %d "
              "relaxations of %d solves in all\n" % (n, zone_n, args.instants, newton, relaxations, solves))
        print("| ranks | incremental s | space-time s | ratio |")
        print("|---:|---:|---:|---:|")
        for P, a, b in zip(ranks, inc, st):
            if P in (1, 2, 8, 64, 256, 1024, 4096, 16384):
                print("| %d | %.4g | %.4g | %.3g |" % (P, a, b, a / b))
        print("\nSaturation (doubling the ranks gains less than 10 %%): incremental at %d ranks, space-time at %d."
              % (saturation(inc, ranks), saturation(st, ranks)))


if __name__ == "__main__":
    main()
