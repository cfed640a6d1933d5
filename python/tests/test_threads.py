"""Threads: registrations against one map from two threads give the
sequential results, and they run at the same time (the GIL is released while
the library works).

Overlap is measured without trusting Python-side timestamps (a thread
waiting for the GIL would look busy): each result's total_time_s is the
wall time inside the library, taken by the library itself. Calls that take
turns add up to at most the elapsed time; calls that run at the same time add
up to more, up to twice it for two threads, on one core as on two."""

import threading
import time

import numpy as np

import mlndt
from conftest import same_result


def jobs(koide3):
    """Inputs and guesses: the koide3 input from three starts, and the
    reference onto itself."""
    reference, input = koide3
    return [
        (input, None),
        (input, mlndt.pose_from_xi([0.3, 0.2, 0.0, 0.0, 0.0, -3.0], degrees=True)),
        (reference, None),
        (input, mlndt.pose_from_xi([1.0, -0.5, 0.0, 0.0, 0.0, 5.0], degrees=True)),
    ]


def run_in_two_threads(work, items):
    """work(item) for items[0::2] in one thread and items[1::2] in another,
    started together; returns the results in item order and the elapsed
    wall time."""
    results = [None] * len(items)
    errors = []
    barrier = threading.Barrier(3)

    def thread(index):
        try:
            barrier.wait()
            for k in range(index, len(items), 2):
                results[k] = work(items[k])
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)

    threads = [threading.Thread(target=thread, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    barrier.wait()
    start = time.perf_counter()
    for t in threads:
        t.join()
    elapsed = time.perf_counter() - start
    assert not errors, errors
    return results, elapsed


def assert_overlapped(results, elapsed):
    inside = sum(r.total_time_s for r in results)
    # Taking turns: inside <= elapsed. Together: up to 2 x elapsed.
    assert inside > 1.4 * elapsed, f"{inside:.3f} s in the library within {elapsed:.3f} s"


def test_two_threads_on_one_map_give_the_sequential_results_and_overlap(koide3):
    reference_map = mlndt.LayeredMap.build(mlndt.filter_range(koide3[0]))
    items = jobs(koide3) * 2
    sequential = [reference_map.register(points, initial=guess) for points, guess in items]
    parallel, elapsed = run_in_two_threads(lambda item: reference_map.register(item[0], initial=item[1]), items)
    for k, (a, b) in enumerate(zip(sequential, parallel)):
        assert same_result(a, b), k
    assert_overlapped(parallel, elapsed)


def test_two_threads_registering_clouds_give_the_sequential_results_and_overlap(koide3):
    items = [koide3] * 6
    sequential = [mlndt.register(*item) for item in items]
    parallel, elapsed = run_in_two_threads(lambda item: mlndt.register(*item), items)
    for a, b in zip(sequential, parallel):
        assert same_result(a, b)
    assert_overlapped(parallel, elapsed)


def python_share_during(call):
    """The share of its normal pace that a pure-Python loop in another
    thread kept while `call` ran in this one. A call that holds the GIL
    lets it run only at the few switches into and out of the call (a few
    switch intervals of 5 ms); a call that releases it lets it run all the
    time on a second core, half of it on a shared one."""
    ticks = [0]
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks[0] += 1

    thread = threading.Thread(target=ticker)
    thread.start()
    time.sleep(0.05)  # Alone: its pace.
    start, before = time.perf_counter(), ticks[0]
    time.sleep(0.1)
    pace = (ticks[0] - before) / (time.perf_counter() - start)
    start, before = time.perf_counter(), ticks[0]
    call()
    elapsed = time.perf_counter() - start
    during = ticks[0] - before
    stop.set()
    thread.join()
    assert elapsed > 0.25, f"make the call longer than {elapsed:.3f} s"
    return during / (pace * elapsed)


def test_python_runs_while_the_library_works(tmp_path, koide3):
    reference, input = koide3
    reference_map = mlndt.LayeredMap.build(reference)
    reference_map.save(tmp_path / "map.mlndtmap")
    mlndt.write_cloud(tmp_path / "cloud.pcd", reference)
    big = np.random.default_rng(1).permutation(1_000_000).tolist()
    # A C call that holds the GIL, to show what the measure says then.
    assert python_share_during(lambda: sorted(big)) < 0.1
    calls = {
        "register": lambda: [mlndt.register(reference, input) for _ in range(8)],
        "LayeredMap.register": lambda: [reference_map.register(input) for _ in range(8)],
        "LayeredMap.build": lambda: [mlndt.LayeredMap.build(reference) for _ in range(40)],
        "LayeredMap.load": lambda: [mlndt.LayeredMap.load(tmp_path / "map.mlndtmap") for _ in range(100)],
        "read_cloud": lambda: [mlndt.read_cloud(tmp_path / "cloud.pcd") for _ in range(40)],
    }
    for name, call in calls.items():
        assert python_share_during(call) > 0.2, name


def test_results_outlive_their_thread(koide3):
    results = []
    thread = threading.Thread(target=lambda: results.append(mlndt.register(*koide3)))
    thread.start()
    thread.join()
    assert results[0].usable
    np.testing.assert_array_equal(results[0].reference_from_input, mlndt.register(*koide3).reference_from_input)
