"""Scale-out on Dask: register many scan pairs, or localise many scans against
one saved map, on the workers of a Dask cluster.

    from distributed import Client
    import mlndt.distributed as md

    client = Client("tcp://scheduler:8786")  # or Client(LocalCluster(...))
    pairs = md.register_pairs(paths, [(0, 1), (1, 2), (0, 2)], client=client)
    scans = md.localize_scans("map.mlndt", scan_paths, initial_poses, client=client)
    print(md.tasks_per_worker(pairs))

One task per pair (or scan). A worker process reads each scan file and
builds each reference map (or loads the saved map) once: a per-process cache
keyed by the file (its path, size and modification time, so a file rewritten
at the same path is read again; and, for built maps, the options) serves its
later tasks.
Workers read the files themselves, so on a cluster the paths must be visible
to every worker (a shared file system). With client=None the same task
function runs here, in order: the sequential run, whose results the
distributed one reproduces exactly (registration is deterministic).

Results come back in the order given, as PairRegistration or
ScanLocalization (plain, picklable records; `worker` is the address of the
worker that ran the task, "local" without a client).
"""

import functools
import json
import os
import threading
from collections import Counter, OrderedDict
from dataclasses import dataclass

import numpy as np

from . import _mlndt

__all__ = [
    "PairRegistration",
    "ScanLocalization",
    "localize_scans",
    "register_pairs",
    "tasks_per_worker",
]

# Per-process caches: scans (an (N, 3) float64 array each; a 120k-point
# KITTI scan is 2.9 MB), built reference maps, loaded map files.
_CLOUD_CACHE_SIZE = 64
_MAP_CACHE_SIZE = 8


@dataclass(frozen=True, eq=False)
class PairRegistration:
    """Scan `input` registered onto scan `reference` (indices into the paths)."""

    reference: int
    input: int
    reference_from_input: np.ndarray  # 4x4
    termination: str
    usable: bool
    score: float
    iterations: int
    worker: str


@dataclass(frozen=True, eq=False)
class ScanLocalization:
    """Scan `index` registered onto the saved map."""

    index: int
    map_from_scan: np.ndarray  # 4x4
    termination: str
    usable: bool
    score: float
    iterations: int
    worker: str


def _worker_address():
    try:
        from distributed import get_worker

        return get_worker().address
    except (ImportError, ValueError):
        return "local"


def _file_key(path):
    """A cache key of the file at `path`: the path, its size and its
    modification time [ns], so a file rewritten at the same path is read
    again."""
    path = os.fspath(path)
    try:
        status = os.stat(path)
    except OSError:
        return (path, None, None)  # The reader names the problem.
    return (path, status.st_size, status.st_mtime_ns)


@functools.lru_cache(maxsize=_CLOUD_CACHE_SIZE)
def _cloud_of(key):
    return _mlndt.read_cloud(key[0])


def _cloud(path):
    return _cloud_of(_file_key(path))


_reference_maps = OrderedDict()  # (file key, options key) -> LayeredMap, oldest first.
_reference_maps_lock = threading.Lock()  # Workers may run several threads.


def _reference_map(path, options):
    """The map mlndt.register builds of the reference (its range-filtered
    points on the options' grid), built once per process and options."""
    key = (_file_key(path), json.dumps(options, sort_keys=True, default=repr))
    with _reference_maps_lock:
        if key in _reference_maps:
            _reference_maps.move_to_end(key)
            return _reference_maps[key]
    full = _mlndt.resolve_options(**options)
    points = _mlndt.filter_range(_cloud(path), **full["range_filter"])
    layered_map = _mlndt.LayeredMap.build(points, **full["grid"])
    with _reference_maps_lock:
        _reference_maps[key] = layered_map
        if len(_reference_maps) > _MAP_CACHE_SIZE:
            _reference_maps.popitem(last=False)
    return layered_map


@functools.lru_cache(maxsize=2)
def _saved_map_of(key):
    return _mlndt.LayeredMap.load(key[0])


def _saved_map(path):
    return _saved_map_of(_file_key(path))


def _register_pair(task, options):
    reference, input, reference_path, input_path, initial, initial_uncertainty = task
    layered_map = _reference_map(reference_path, options)
    register_options = {k: v for k, v in options.items() if k != "grid"}
    result = layered_map.register(_cloud(input_path), initial, initial_uncertainty, **register_options)
    return PairRegistration(
        reference,
        input,
        result.reference_from_input,
        result.termination_type,
        result.usable,
        result.final_score,
        result.num_iterations,
        _worker_address(),
    )


def _localize_scan(task, map_path, options):
    index, scan_path, initial, initial_uncertainty = task
    result = _saved_map(map_path).register(_mlndt.read_cloud(scan_path), initial, initial_uncertainty, **options)
    return ScanLocalization(
        index,
        result.reference_from_input,
        result.termination_type,
        result.usable,
        result.final_score,
        result.num_iterations,
        _worker_address(),
    )


def _run(function, tasks, client):
    if client is None:
        return [function(task) for task in tasks]
    futures = client.map(function, tasks, pure=False)
    return client.gather(futures)


def _guesses(initial, count, name):
    if initial is None:
        return [None] * count
    guesses = np.asarray(initial, dtype=float)
    if guesses.ndim != 3 or guesses.shape[0] != count or guesses.shape[1:] not in ((4, 4), (3, 4)):
        raise ValueError(f"{name}: expected ({count}, 4, 4) transforms, got shape {guesses.shape}")
    return list(guesses)


def register_pairs(paths, pairs, initial=None, initial_uncertainty=None, client=None, **options):
    """register_pairs(paths, pairs, initial=None, initial_uncertainty=None, client=None, **options)
        -> list[PairRegistration]

    Registers scan j onto scan i for every (i, j) in `pairs` (indices into
    `paths`), as mlndt.register(read_cloud(paths[i]), read_cloud(paths[j]),
    initial[k], initial_uncertainty, **options) would, on the workers of
    `client` (None: here, in order). initial: None (identity) or (len(pairs),
    4, 4) guesses of reference_from_input. The options are mlndt.register's;
    they are checked here before any task is sent (ValueError naming the field).
    """
    paths = [str(p) for p in paths]
    pairs = [(int(i), int(j)) for i, j in pairs]
    for k, (i, j) in enumerate(pairs):
        if not (0 <= i < len(paths) and 0 <= j < len(paths)):
            raise ValueError(f"pairs[{k}] = ({i}, {j}): indices must be in [0, {len(paths)})")
    _validate(options, initial_uncertainty, map_given=False)
    guesses = _guesses(initial, len(pairs), "initial")
    tasks = [(i, j, paths[i], paths[j], guesses[k], initial_uncertainty) for k, (i, j) in enumerate(pairs)]
    return _run(functools.partial(_register_pair, options=options), tasks, client)


def localize_scans(map_path, scan_paths, initial=None, initial_uncertainty=None, client=None, **options):
    """localize_scans(map_path, scan_paths, initial=None, initial_uncertainty=None, client=None, **options)
        -> list[ScanLocalization]

    Registers every scan onto the saved map (LayeredMap.load(map_path), read
    once per worker) from its own guess: initial is None (identity) or
    (len(scan_paths), 4, 4) map_from_scan guesses (odometry, GNSS). Unlike
    mlndt.Localizer, no scan depends on another's result, so the scans run
    in parallel. Options as LayeredMap.register (checked here first).
    """
    map_path = str(map_path)
    scan_paths = [str(p) for p in scan_paths]
    _validate(options, initial_uncertainty, map_given=True)
    guesses = _guesses(initial, len(scan_paths), "initial")
    tasks = [(k, path, guesses[k], initial_uncertainty) for k, path in enumerate(scan_paths)]
    return _run(functools.partial(_localize_scan, map_path=map_path, options=options), tasks, client)


def tasks_per_worker(results):
    """{worker address: number of results it computed}."""
    return dict(Counter(result.worker for result in results))


def _validate(options, initial_uncertainty, map_given):
    """Raises the ValueError the workers' registrations would, before any
    task is sent."""
    if map_given and "grid" in options:
        raise ValueError("invalid option: grid does not apply to a saved map (it was built with its own)")
    _mlndt.resolve_options(initial_uncertainty, **options)
