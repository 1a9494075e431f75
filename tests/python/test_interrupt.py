"""Long solves release the interpreter's lock and stop on Ctrl-C with KeyboardInterrupt."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import stcontact
from conftest import SEED_SCENE

# A solve that runs for many seconds unless stopped: plain LATIN on a long time grid (about 20 ms
# an iteration) to an unreachable tolerance (it would stop as stagnated hundreds of iterations on).
LONG_GRID = ["time.steps=3201", "output.frames=false"]  # ~40 ms per LATIN iteration: room for ticks between callbacks
ENDLESS = dict(solver="latin", tol=1e-30, max_iterations=1_000_000, reference=False)


@pytest.fixture(scope="module")
def long_scene():
    return stcontact.load_scene(SEED_SCENE, sets=LONG_GRID)


def test_sigint_during_a_solve_raises_keyboard_interrupt(long_scene):
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            stcontact.solve(long_scene, **ENDLESS)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 5.0  # stopped at the next iteration, not at the end


def test_sigint_during_a_phase_without_records_raises_keyboard_interrupt():
    """fas-apriori's sub-grid of instants (nested iteration in time) makes no record of the solve, so
    the callback is not called there: here, held at an unreachable tolerance, it runs about 18 s (2000
    relaxations on 2001 instants) before the whole grid's first record. Ctrl-C is heard between its
    relaxations all the same (the module's StopProbe, src/core/interruption.hpp)."""
    records = []
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            stcontact.solve(SEED_SCENE, "fas-apriori", tol=1e-30, max_iterations=1_000_000, reference=False,
                            sets=["time.steps=20001", "output.frames=false", "solver.nested_tolerance=1e-30"],
                            callback=records.append, spatial_modes=False)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 5.0 and records == []  # stopped within the sub-grid


def test_other_threads_run_while_the_solver_computes(long_scene):
    """A second thread ticks every millisecond. Had the solve held the lock, it could tick only while
    the main thread runs Python code, i.e. inside the callbacks (and a moment after them); it ticks
    between them too, while the solver computes."""
    ticks, windows = [], []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    def record_window(record):
        windows.append(time.monotonic())
        return record.iteration < 30

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        result = stcontact.solve(long_scene, callback=record_window, **ENDLESS)
    finally:
        stop.set()
        ticker.join()
    assert result.termination == "stopped_by_callback" and len(windows) == 30
    margin = 0.005  # after a callback returns, before the solver is surely back in its own code
    between = [t for t in ticks if any(a + margin < t < b - margin for a, b in zip(windows, windows[1:]))]
    assert len(between) >= 29, "the other thread did not run while the solver computed"


def test_ctrl_c_stops_a_script(tmp_path):
    script = tmp_path / "endless.py"
    script.write_text(textwrap.dedent("""
        import sys, stcontact
        scene = stcontact.load_scene(sys.argv[1], sets=["time.steps=801"])
        print("solving", flush=True)
        stcontact.solve(scene, "latin", tol=1e-30, max_iterations=1000000, reference=False)
        print("finished", flush=True)
    """))
    child = subprocess.Popen([sys.executable, str(script), str(SEED_SCENE)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "solving"
        time.sleep(0.5)
        child.send_signal(signal.SIGINT)
        stdout, stderr = child.communicate(timeout=20)
    finally:
        child.kill()
    assert child.returncode != 0 and "finished" not in stdout
    assert stderr.strip().splitlines()[-1] == "KeyboardInterrupt"
