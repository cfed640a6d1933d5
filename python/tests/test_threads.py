"""Threads: registrations against one map from two threads give the
sequential results, and Python keeps running in other threads while the
library works (the GIL is released). How much two threads gain in wall time
depends on the machine's load: that is a benchmark's figure, not a test's."""

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
    started together; returns the results in item order."""
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
    for t in threads:
        t.join()
    assert not errors, errors
    return results


def test_two_threads_on_one_map_give_the_sequential_results(koide3):
    reference_map = mlndt.LayeredMap.build(mlndt.filter_range(koide3[0]))
    items = jobs(koide3) * 2
    sequential = [reference_map.register(points, initial=guess) for points, guess in items]
    parallel = run_in_two_threads(lambda item: reference_map.register(item[0], initial=item[1]), items)
    for k, (a, b) in enumerate(zip(sequential, parallel)):
        assert same_result(a, b), k


def test_two_threads_registering_clouds_give_the_sequential_results(koide3):
    items = [koide3] * 6
    sequential = [mlndt.register(*item) for item in items]
    parallel = run_in_two_threads(lambda item: mlndt.register(*item), items)
    for a, b in zip(sequential, parallel):
        assert same_result(a, b)


def python_ticks_per_second_during(call):
    """How fast a pure-Python loop in another thread counts while `call`
    runs in this one (again and again for at least 0.3 s). A call that holds the GIL lets the loop run only at the
    switches into and out of it; a call that releases it lets the loop run
    all along (on a second core, or sharing this one)."""
    ticks = [0]
    running = threading.Event()
    stop = threading.Event()

    def ticker():
        running.set()
        while not stop.is_set():
            ticks[0] += 1

    thread = threading.Thread(target=ticker)
    thread.start()
    running.wait()
    start, before = time.perf_counter(), ticks[0]
    call()
    while time.perf_counter() - start < 0.3:  # Switches at the ends get rare.
        call()
    elapsed = time.perf_counter() - start
    during = ticks[0] - before
    stop.set()
    thread.join()
    return during / elapsed


def test_python_runs_while_the_library_works(tmp_path, koide3):
    reference, input = koide3
    reference_map = mlndt.LayeredMap.build(reference)
    reference_map.save(tmp_path / "map.mlndtmap")
    mlndt.write_cloud(tmp_path / "cloud.pcd", reference)
    big = np.random.default_rng(1).permutation(1_000_000).tolist()
    calls = {
        "register": lambda: [mlndt.register(reference, input) for _ in range(8)],
        "LayeredMap.register": lambda: [reference_map.register(input) for _ in range(8)],
        "LayeredMap.build": lambda: [mlndt.LayeredMap.build(reference) for _ in range(40)],
        "LayeredMap.load": lambda: [mlndt.LayeredMap.load(tmp_path / "map.mlndtmap") for _ in range(100)],
        "read_cloud": lambda: [mlndt.read_cloud(tmp_path / "cloud.pcd") for _ in range(40)],
    }
    for name, call in calls.items():
        # Against a C call that holds the GIL (sorting a list), timed alike.
        holding = python_ticks_per_second_during(lambda: [sorted(big) for _ in range(2)])
        releasing = python_ticks_per_second_during(call)
        assert releasing > 5 * holding, f"{name}: {releasing:.0f} ticks/s, {holding:.0f} holding the GIL"


def test_results_outlive_their_thread(koide3):
    results = []
    thread = threading.Thread(target=lambda: results.append(mlndt.register(*koide3)))
    thread.start()
    thread.join()
    assert results[0].usable
    np.testing.assert_array_equal(results[0].reference_from_input, mlndt.register(*koide3).reference_from_input)
