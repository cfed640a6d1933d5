"""The Python keywords against the one option description (the library's
option tables, printed by mlndt_options --format=json): every described field
of RegistrationOptions is a keyword at its path with the same default, no
keyword is undescribed, a value outside a field's range is refused naming the
field, every field of the tools' own tables that Python reaches is a keyword
of its class documented with the same default, and docs/options.md is the
current description."""

import json
import re
import subprocess

import pytest

import mlndt
from conftest import KITTI_SCANS, SOURCE_DIR, TOOLS_DIR

# Fields that are Python keywords but not flags (the --initial_uncertainty=t,r
# flag sets them); they are described all the same.
PYTHON_ONLY = {"initial_uncertainty.given", "initial_uncertainty.translation_m", "initial_uncertainty.rotation_deg"}


def run_options_tool(*args):
    proc = subprocess.run([str(TOOLS_DIR / "mlndt_options"), *args], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


@pytest.fixture(scope="module")
def description():
    return json.loads(run_options_tool("--format=json"))


def flatten(options, prefix=""):
    out = {}
    for key, value in options.items():
        if isinstance(value, dict):
            out.update(flatten(value, prefix + key + "."))
        else:
            out[prefix + key] = value
    return out


def same_default(python_value, text, kind):
    if kind == "bool":
        return python_value is (text == "true")
    if kind in ("int", "uint64"):
        return python_value == int(text)
    if kind == "double":
        return python_value == float(text)
    if kind == "list of double":
        return python_value == ([float(v) for v in text.split(",")] if text else [])
    return python_value.lower() == text  # enum: C++ name vs lower-case flag text


def test_every_described_field_is_a_keyword_with_its_default(description):
    keywords = flatten(mlndt.default_options())
    described = {row["mlndt_path"]: row for row in description["options"] if row["mlndt_path"]}
    for path, row in described.items():
        assert path in keywords, f"{path} (--{row['flag']}) is no Python keyword"
        assert same_default(keywords[path], row["default"], row["type"]), (path, keywords[path], row["default"])
    undescribed = set(keywords) - set(described) - PYTHON_ONLY
    assert not undescribed, f"keywords without a description: {sorted(undescribed)}"


def test_every_range_bound_is_refused_naming_the_field(description):
    checked = 0
    for row in description["options"]:
        path, valid = row["mlndt_path"], row["range"]
        if not path or not valid.startswith("in [") or row["type"] not in ("int", "double"):
            continue
        low = float(valid[len("in [") :].split(",")[0])
        bad = low - 1 if row["type"] == "int" else low - max(abs(low) * 0.5, 1e-3)
        if " or 0" in valid and bad == 0:
            continue
        *parents, leaf = path.split(".")
        kwargs = value = {leaf: int(bad) if row["type"] == "int" else bad}
        for parent in reversed(parents):
            kwargs = {parent: kwargs}
        with pytest.raises(ValueError, match=r"invalid option: " + path.replace(".", r"\.") + " = "):
            mlndt.resolve_options(**kwargs)
        checked += 1
        del value
    assert checked >= 20


def test_docstring_carries_units_and_ranges():
    doc = mlndt.register.__doc__
    assert "loss_scale: float = 1.5" in doc
    assert "Mahalanobis distance sqrt(s) where the robust loss bends. In [0.001, 1000]." in doc
    assert "residual: str: WHITENED | SCALAR_SCORE" in doc


def test_docs_options_md_is_current():
    assert (SOURCE_DIR / "docs" / "options.md").read_text() == run_options_tool()


# The tools' own tables (mlndt_options' "tool_options") and where Python
# reaches them: LocalizerOptions' fields are mlndt.Localizer keywords;
# MapBuildOptions is mlndt_map's only (LayeredMap.build takes the grid
# keywords and num_threads, not a voxel filter or a memory limit);
# TrajectoryEvaluationOptions, AdaptiveStartLayerOptions, PoseGraphOptions,
# SequenceOptions, SuitePlanOptions and BenchOptions are the lab's
# (mlndt_eval, mlndt_sequence, mlndt_posegraph, mlndt_suite, mlndt_bench).
PYTHON_TOOL_TABLES = {"LocalizerOptions": lambda: mlndt.Localizer}
TOOL_ONLY_TABLES = {
    "MapBuildOptions",
    "TrajectoryEvaluationOptions",
    "AdaptiveStartLayerOptions",
    "PoseGraphOptions",
    "SequenceOptions",
    "SuitePlanOptions",
    "BenchOptions",
}
# OdometryOptions' fields are mlndt.Odometry keywords, a nested struct's as a
# dict (local_map={"max_keyframes": 3} for --local_map_max_keyframes=3).
NESTED_TOOL_TABLES = {"OdometryOptions": lambda: mlndt.Odometry}


def test_every_tool_table_has_its_python_place(description):
    structs = {table["struct"] for table in description["tool_options"]}
    assert structs == set(PYTHON_TOOL_TABLES) | TOOL_ONLY_TABLES | set(NESTED_TOOL_TABLES)


def test_nested_tool_table_fields_are_keywords(description):
    checked = 0
    for table in description["tool_options"]:
        if table["struct"] not in NESTED_TOOL_TABLES:
            continue
        cls = NESTED_TOOL_TABLES[table["struct"]]()
        for row in table["options"]:
            path, kind = row["field"], row["type"]
            assert row["flag"] in ("", path.replace(".", "_")), row
            cls(**as_keyword(path, python_value(row["default"], kind)))  # A keyword.
            with pytest.raises(ValueError, match=re.escape(path)):
                cls(**as_keyword(path, object()))
            checked += 1
    assert checked >= 16


def documented_defaults(doc):
    """{name: default} of the "    name: type = default" lines a table's
    description puts into a docstring; a nested struct's fields, indented
    below its "    name: dict (...)" line, as "name.field"."""
    found, outer = {}, None
    for m in re.finditer(r"^(    |        )(\w+): (.+)$", doc, re.M):
        indent, name, rest = m.groups()
        if len(indent) == 4:
            outer = name if rest.startswith("dict") else None
        if " = " not in rest:
            continue
        key = name if len(indent) == 4 else f"{outer}.{name}"
        found[key] = rest.rsplit(" = ", 1)[1].strip('"')
    return found


def as_keyword(path, value):
    """The keyword of a field path: {"a": v}, or {"a": {"b": v}} for "a.b"."""
    if "." not in path:
        return {path: value}
    outer, inner = path.split(".")
    return {outer: {inner: value}}


def python_value(text, kind):
    if kind == "bool":
        return text in ("true", "True")
    if kind in ("int", "uint64"):
        return int(text)
    if kind == "double":
        return float(text)
    return text


@pytest.fixture(scope="module")
def small_map():
    return mlndt.LayeredMap.build(mlndt.filter_range(mlndt.read_cloud(KITTI_SCANS[0])))


def test_tool_table_fields_are_keywords_with_their_defaults(description, small_map):
    checked = 0
    for table in description["tool_options"]:
        if table["struct"] not in PYTHON_TOOL_TABLES:
            continue
        cls = PYTHON_TOOL_TABLES[table["struct"]]()
        documented = documented_defaults(cls.__init__.__doc__)
        for row in table["options"]:
            name, kind = row["field"], row["type"]
            assert name in documented, f"{table['struct']}.{name} is not documented by {cls.__name__}"
            assert same_default(python_value(documented[name], kind), row["default"], kind), (name, documented[name])
            cls(small_map, **as_keyword(name, python_value(row["default"], kind)))  # A keyword.
            with pytest.raises(ValueError, match=r"invalid option: " + re.escape(name) + " = "):
                cls(small_map, **as_keyword(name, object()))
            checked += 1
    assert checked >= 1
