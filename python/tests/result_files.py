"""Reading a tool's scans.csv and scans.json against Python's todict(): the
files and Python name and value a result's fields alike (issue 46)."""

import numpy as np

# Lists of nested results: in JSON and Python, no CSV column.
LISTS = ("trace", "bridged")


def flatten(value, prefix=""):
    """A todict() or a JSON object as the CSV's columns: nested dicts as
    "outer.inner", lists of results (LISTS) left out; {column: value}."""
    columns = {}
    for key, item in value.items():
        name = prefix + key
        if isinstance(item, dict):
            columns.update(flatten(item, name + "."))
        elif key not in LISTS:
            columns[name] = item
    return columns


def csv_cell(text, like=None):
    """A CSV cell as a value: bools, numbers, space-separated numbers; an
    empty cell is an empty string or, when `like` (the value it stands for)
    is a list or array, an empty list."""
    if text == "":
        return [] if isinstance(like, (list, tuple, np.ndarray)) else ""
    if text in ("true", "false"):
        return text == "true"
    try:
        numbers = [float(x) for x in text.split()]
    except ValueError:
        return text
    return numbers[0] if len(numbers) == 1 and " " not in text else numbers


def as_numbers(value):
    """A Python or JSON value as a flat list of floats (None is NaN)."""
    if isinstance(value, (bool, str)):
        return value
    array = np.asarray(value, dtype=float).ravel()
    return [float(x) for x in array]


def same(a, b):
    a, b = as_numbers(a), as_numbers(b)
    if isinstance(a, (bool, str)) or isinstance(b, (bool, str)):
        return a == b
    return len(a) == len(b) and all(x == y or (np.isnan(x) and np.isnan(y)) for x, y in zip(a, b))


def none_to_nan(value):
    if value is None:
        return float("nan")
    if isinstance(value, list):
        return [none_to_nan(v) for v in value]
    return value


def is_time(name):
    """A wall time (differs between two runs): *_time_s, a record's time_s."""
    return name.split(".")[-1] == "time_s" or name.endswith("_time_s")


def assert_files_agree_with_python(row, scan, python, skip_times):
    """One result: its CSV row and JSON object (without "file") against its
    todict(): the same keys in the same order, the same values (wall times
    only between the files when `skip_times`: Python ran separately)."""
    assert list(scan) == list(python)
    assert "trace" not in scan["registration"]
    flat = flatten(python)
    json_flat = flatten(scan)
    assert list(row) == list(flat) == list(json_flat)
    for name, value in flat.items():
        cell = csv_cell(row[name], value)
        assert same(cell, none_to_nan(json_flat[name])), (name, row[name], json_flat[name])
        if skip_times and is_time(name):
            continue
        assert same(cell, value), (name, row[name], value)
