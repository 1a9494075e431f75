#!/usr/bin/env python3
"""A probe of the program's promises, as a user who abuses it would test them (docs/reliability.md):

  stopping   solves at values drawn (seeded) across every range of [solver] and [material] keys,
             every iterative strategy, 2D, 3D, two bodies: a run that says converged must have its
             true error at most the tolerance (no silent wrong answer);
  files      run folders holding files of one's own (hidden files, links, empty folders, a file
             under a name a run writes, a marker edited by hand): nothing of one's own is deleted,
             the run refuses and names it;
  signals    SIGTERM, SIGINT and SIGHUP at random moments of check, solve, compare, sweep and svd on
             scenes of a few seconds: the run ends within 3 s with 128 + the signal, nothing is
             left beside its folder, the folder is the previous run or absent;
  inputs     special files (a FIFO, /dev/null, /proc files, a folder), counts that only count
             cycles, names with control characters: refused by name, fast, nothing created.

Usage: scripts/trust_probe.py PROGRAM [--runs N] [--seed S] [--out DIR] [--markdown]
Prints one line per run that breaks a promise, then a summary table (markdown with --markdown).
Exit status: 0 no broken promise, 1 some.
"""
import argparse
import json
import math
import os
import random
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.path.join(ROOT, 'examples', 'scenes')
STRATEGIES = ['latin', 'latin-pgd', 'fas-aposteriori', 'fas-apriori']
# Small settings of scenes of every kind: 2D, 3D, two bodies, a Gmsh mesh, a moving obstacle.
SMALL = {
    'hemicylinder.toml': ['mesh.arc_nodes=25', 'time.steps=15'],
    'hemisphere.toml': ['mesh.divisions=3', 'time.steps=9'],
    'two_cylinders.toml': ['mesh.arc_nodes=25', 'time.steps=11'],
    'punch.toml': ['time.steps=11'],
    'moving_pad.toml': ['time.steps=21'],
    'fretting.toml': ['mesh.arc_nodes=25', 'time.steps=41'],
}


def log_uniform(rng, low, high):
    return math.exp(rng.uniform(math.log(low), math.log(high)))


# [solver] and material keys, each with a draw over its documented range (ends included).
DRAWS = {
    'solver.relaxation': lambda r: r.choice([log_uniform(r, 1e-9, 1.0), 1.0, 1e-300]),
    'solver.search_scale': lambda r: log_uniform(r, 1e-3, 1e3),
    'solver.tolerance': lambda r: log_uniform(r, 1e-11, 1e-2),
    'solver.pgd_gap_share': lambda r: r.choice([log_uniform(r, 1e-12, 0.5), 1 - log_uniform(r, 1e-12, 0.5)]),
    'solver.pgd_full_share': lambda r: r.uniform(1e-6, 1.0),
    'solver.coarse_iterations': lambda r: r.choice([1, 2, 16, 200]),
    'solver.pre_relaxations': lambda r: r.choice([1, 2, 5]),
    'solver.post_relaxations': lambda r: r.choice([0, 1, 3]),
    'solver.zone_margin': lambda r: r.uniform(0.0, 1.0),
    'solver.nested_instants': lambda r: r.choice([0, 3, 5, 9]),
    'material.poisson': lambda r: r.choice([r.uniform(-0.999999, 0.4999995), -0.999999, 0.4999995,
                                            0.5 - log_uniform(r, 5e-7, 1e-2), -1 + log_uniform(r, 1e-6, 1e-2)]),
    'material.young': lambda r: log_uniform(r, 1e-100, 1e100),
    'contact.friction': lambda r: r.choice([0.0, log_uniform(r, 1e-8, 1e4)]),
}


def run(cmd, timeout=120, **kw):
    start = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, **kw)
        return p.returncode, p.stdout, p.stderr, time.time() - start
    except subprocess.TimeoutExpired:
        return None, '', 'timeout', time.time() - start


class Probe:
    def __init__(self, program, work, rng):
        self.program, self.work, self.rng = program, work, rng
        self.rows = {}     # category -> [runs, broken]
        self.broken = []

    def count(self, category, ok, what):
        runs = self.rows.setdefault(category, [0, 0])
        runs[0] += 1
        if not ok:
            runs[1] += 1
            self.broken.append('%s: %s' % (category, what))
            print('BROKEN %s: %s' % (category, what), flush=True)

    # -- stopping: converged means true error <= tolerance
    def stopping(self, runs):
        for i in range(runs):
            scene = self.rng.choice(sorted(SMALL))
            strategy = self.rng.choice(STRATEGIES)
            keys = self.rng.sample(sorted(DRAWS), self.rng.choice([1, 2, 3]))
            sets = SMALL[scene] + ['%s=%.17g' % (k, DRAWS[k](self.rng)) for k in keys] + ['solver.max_iterations=300',
                                                                                      'output.frames=false']
            out = os.path.join(self.work, 'stop_%d' % i)
            cmd = [self.program, 'solve', os.path.join(SCENES, scene), '--solver', strategy, '--quiet', '--out', out]
            for s in sets:
                cmd += ['--set', s]
            code, _, err, _ = run(cmd)
            what = '%s %s %s' % (scene, strategy, ' '.join(sets[len(SMALL[scene]):-2]))
            if code is None:
                self.count('stopping', False, what + ': no answer within 120 s')
                continue
            if code == 1:  # refused, naming a key
                self.count('stopping', err.startswith('error: '), what + ': refused without an error line: ' + err)
                continue
            summary = json.load(open(os.path.join(out, 'summary.json')))
            tolerance = summary['parameters'].get('solver', {}).get('tolerance', 1e-6)
            converged = summary['termination'] == 'converged'
            error = summary['error']
            ok = code in (0, 2) and (not converged or error is None or error <= tolerance)
            self.count('stopping', ok, '%s: %s with true error %s > tolerance %s' % (
                what, summary['termination'], error, tolerance))
            shutil.rmtree(out, ignore_errors=True)

    # -- files: nothing of one's own is deleted
    def files(self, runs):
        seed = os.path.join(SCENES, 'hemicylinder.toml')
        base = [self.program, 'solve', seed, '--solver', 'latin', '--quiet', '--set', 'mesh.arc_nodes=21',
                '--set', 'time.steps=21', '--set', 'output.frame_stride=10', '--set', 'output.format="vtu"']
        kinds = ['hidden', 'link', 'empty_dir', 'output_name_in_subdir', 'csv_of_ones_own', 'deep', 'fifo',
                 'readonly_file', 'nested_run', 'vtu_extra']
        for i in range(runs):
            kind = kinds[i % len(kinds)]
            out = os.path.join(self.work, 'files_%d' % i)
            code, _, err, _ = run(base + ['--out', out])
            if code != 0:
                self.count('files', False, 'first run failed: ' + err)
                continue
            own = self.place(kind, out)
            code, _, err, _ = run(base + ['--out', out])
            kept = os.path.lexists(own)
            self.count('files', kept and code == 1 and 'which its run did not write' in err,
                       '%s: exit %s, kept %s, %s' % (kind, code, kept, err.strip()))
            shutil.rmtree(out, ignore_errors=True)

    def place(self, kind, out):
        r = self.rng
        if kind == 'hidden':
            path = os.path.join(out, '.notes%d' % r.randrange(1000))
            open(path, 'w').write('mine')
        elif kind == 'link':
            path = os.path.join(out, 'link_to_home')
            os.symlink(os.path.expanduser('~'), path)
        elif kind == 'empty_dir':
            path = os.path.join(out, 'plots')
            os.mkdir(path)
        elif kind == 'output_name_in_subdir':
            path = os.path.join(out, 'old', 'summary.json')
            os.makedirs(os.path.dirname(path))
            open(path, 'w').write('{}')
        elif kind == 'csv_of_ones_own':
            path = os.path.join(out, 'mine.csv')
            open(path, 'w').write('1,2')
        elif kind == 'deep':
            path = os.path.join(out, 'a', 'b', 'c', 'd.txt')
            os.makedirs(os.path.dirname(path))
            open(path, 'w').write('mine')
        elif kind == 'fifo':
            path = os.path.join(out, 'pipe')
            os.mkfifo(path)
        elif kind == 'readonly_file':
            path = os.path.join(out, 'ro.txt')
            open(path, 'w').write('mine')
            os.chmod(path, stat.S_IRUSR)
        elif kind == 'nested_run':
            path = os.path.join(out, 'inner')
            subprocess.run([self.program, 'solve', os.path.join(SCENES, 'hemicylinder.toml'), '--solver',
                            'incremental', '--quiet', '--set', 'mesh.arc_nodes=21', '--set', 'time.steps=5',
                            '--out', path], check=True)
        else:
            path = os.path.join(out, 'vtu', 'step_99999.vtu')
            open(path, 'w').write('mine')
        return path

    # -- signals: every run stops
    def signals(self, runs):
        commands = [
            ['check', os.path.join(SCENES, 'hemisphere.toml'), '--set', 'mesh.divisions=22'],
            ['solve', os.path.join(SCENES, 'hemisphere.toml'), '--set', 'mesh.divisions=16', '--quiet'],
            ['solve', os.path.join(SCENES, 'hemicylinder.toml'), '--set', 'mesh.arc_nodes=801', '--quiet'],
            ['compare', os.path.join(SCENES, 'hemicylinder.toml'), '--repeats', '2', '--quiet'],
            ['sweep', os.path.join(SCENES, 'hemicylinder.toml'), '--set-range', 'contact.friction=0.1:0.3:4', '--quiet'],
            ['svd', os.path.join(SCENES, 'hemicylinder.toml'), '--set', 'time.steps=801'],
        ]
        for i in range(runs):
            args = self.rng.choice(commands)
            sig = self.rng.choice([signal.SIGTERM, signal.SIGINT, signal.SIGHUP])
            out = os.path.join(self.work, 'signal_%d' % i)
            cmd = [self.program] + args + ([] if args[0] == 'check' else ['--out', out])
            p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            time.sleep(self.rng.uniform(0.05, 3.0))
            sent = time.time()
            p.send_signal(sig)
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                self.count('signals', False, '%s, SIG%s: still running 10 s later' % (args[0], sig.name))
                continue
            took = time.time() - sent
            left = [e for e in os.listdir(self.work) if e.startswith('.signal_%d.' % i)]
            finished = p.returncode in (0, 2)  # it ended before the signal arrived
            ok = (finished or p.returncode == 128 + sig) and took < 3.0 and not left and (
                finished or not os.path.exists(out))
            self.count('signals', ok, '%s, %s after %.1f s: exit %s, %.1f s to stop, left %s' % (
                args[0], sig.name, 0, p.returncode, took, left))
            shutil.rmtree(out, ignore_errors=True)

    # -- inputs: refused by name, fast, nothing created
    def inputs(self, runs):
        fifo = os.path.join(self.work, 'scene.fifo')
        os.mkfifo(fifo)
        folder = os.path.join(self.work, 'a_folder')
        os.mkdir(folder)
        seed = os.path.join(SCENES, 'hemicylinder.toml')
        cases = [
            (['check', '/dev/null'], 'not a regular file'),
            (['check', fifo], 'not a regular file'),
            (['check', '/proc/self/status'], 'not a regular file|TOML|unknown key|missing'),
            (['check', folder], 'is a folder'),
            (['solve', '/dev/zero'], 'not a regular file'),
            (['check', seed, '--set', 'mesh.file="/dev/urandom"', '--set', 'mesh.generator=""'], 'exclude each other|regular'),
            (['check', os.path.join(SCENES, 'punch.toml'), '--set', 'mesh.file="%s"' % fifo], 'not a regular file'),
            (['check', seed, '--set', 'dirichlet[1].times=[0.0, 0.1]', '--set', 'dirichlet[1].values=[0.0, 0.0]',
              '--set', 'dirichlet[1].period=0.1', '--set', 'dirichlet[1].cycles=2147483647'], ''),
            (['check', seed, '--set', 'name="tab\\tname"'], 'control character'),
            (['check', seed, '--set', 'name="line\\nbreak"'], 'control character'),
            (['check', seed, '--set', 'time.end=1e-320'], 'larger time.end'),
            (['check', seed, '--set', 'material.poisson=-0.99999999'], 'out of range'),
            (['check', seed, '--set', 'material.poisson=0.49999999'], 'out of range'),
            (['compare', seed, '--solvers', 'latin,,fas-apriori'], 'empty name'),
            (['compare', seed, '--solvers', 'latin, '], 'empty name'),
            (['frob', seed], "unknown command 'frob'"),
        ]
        for i in range(runs):
            args, pattern = cases[i % len(cases)]
            cwd = tempfile.mkdtemp(dir=self.work)
            code, _, err, took = run([self.program] + args, timeout=30, cwd=cwd)
            created = os.listdir(cwd)
            import re
            if pattern:
                ok = code == 1 and re.search(pattern, err) is not None and took < 10 and not created
            else:
                ok = code == 0 and took < 10
            self.count('inputs', ok, '%s: exit %s in %.1f s, created %s: %s' % (' '.join(args), code, took, created,
                                                                              err.strip()[:200]))
            shutil.rmtree(cwd, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('program')
    parser.add_argument('--runs', type=int, default=300, help='runs in all (stopping 60 %%, files, signals, inputs)')
    parser.add_argument('--seed', type=int, default=20261202)
    parser.add_argument('--out', help='work folder (default: a temporary one, removed)')
    parser.add_argument('--markdown', action='store_true')
    a = parser.parse_args()
    program = os.path.abspath(a.program)
    work = a.out or tempfile.mkdtemp(prefix='trust_probe_')
    os.makedirs(work, exist_ok=True)
    probe = Probe(program, work, random.Random(a.seed))
    share = {'stopping': 0.6, 'files': 0.13, 'signals': 0.13, 'inputs': 0.14}
    start = time.time()
    probe.stopping(int(a.runs * share['stopping']))
    probe.files(int(a.runs * share['files']))
    probe.signals(int(a.runs * share['signals']))
    probe.inputs(a.runs - sum(int(a.runs * share[k]) for k in ('stopping', 'files', 'signals')))
    if not a.out:
        shutil.rmtree(work, ignore_errors=True)
    total = sum(r[0] for r in probe.rows.values())
    broken = sum(r[1] for r in probe.rows.values())
    if a.markdown:
        print('| promise | runs | broken |')
        print('|---|---:|---:|')
        for name in ('stopping', 'files', 'signals', 'inputs'):
            if name in probe.rows:
                print('| %s | %d | %d |' % (name, probe.rows[name][0], probe.rows[name][1]))
        print('| all | %d | %d |' % (total, broken))
    print('%d runs in %.0f s, %d broken promises (seed %d)' % (total, time.time() - start, broken, a.seed))
    return 1 if broken else 0


if __name__ == '__main__':
    sys.exit(main())
