"""threads= applies to its call alone: solves on two Python threads at once, each with its own count,
run with and record their own count, and leave the process's count as it was."""

import threading

import numpy as np

import stcontact

WAIT_S = 120  # far beyond a small solve: a wait that times out fails the test instead of hanging it


def test_concurrent_solves_each_record_their_own_thread_count(small_scene):
    # The calls overlap without nesting: `one` begins, `two` begins, `one` ends while `two` is inside
    # its solve, then `two` ends. A process-wide count set and restored by each call (before the
    # fix) had `one` record two's count.
    one_started, two_started, one_done = threading.Event(), threading.Event(), threading.Event()
    results, errors = {}, []

    def one_waits_for_two(record):
        if record.iteration == 1:
            one_started.set()
            assert two_started.wait(WAIT_S)

    def two_waits_for_one(record):
        if record.iteration == 1:
            two_started.set()
            assert one_done.wait(WAIT_S)

    def solve(name, threads, callback, done=None, after=None):
        try:
            if after is not None:
                assert after.wait(WAIT_S)
            results[name] = stcontact.solve(small_scene, "latin", max_iterations=20, reference=False, threads=threads,
                                            callback=callback)
        except BaseException as error:  # reported by the main thread
            errors.append(error)
        finally:
            if done is not None:
                done.set()

    before = stcontact.solve(small_scene, "latin", max_iterations=1, reference=False).summary["threads"]
    one = threading.Thread(target=solve, args=("one", 1, one_waits_for_two, one_done))
    two = threading.Thread(target=solve, args=("two", 2, two_waits_for_one, None, one_started))
    one.start()
    two.start()
    one.join(2 * WAIT_S)
    two.join(2 * WAIT_S)
    assert not errors, errors
    assert results["one"].summary["threads"] == 1 and results["two"].summary["threads"] == 2
    assert results["one"].iterations == results["two"].iterations == 20
    np.testing.assert_array_equal(results["one"].interface_forces, results["two"].interface_forces)
    after = stcontact.solve(small_scene, "latin", max_iterations=1, reference=False).summary["threads"]
    assert after == before
