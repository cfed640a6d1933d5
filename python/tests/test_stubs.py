"""Docstrings and type stubs: help() shows the parameters and every option,
and python/mlndt/__init__.pyi matches the module (a field added to a C++
option struct and bound in python/src/options.cc must be added to the stub)."""

import ast
import importlib.util
import pydoc
import subprocess
import types

import pytest

import mlndt
from conftest import BUILD_DIR, SOURCE_DIR

STUB = SOURCE_DIR / "python" / "mlndt" / "__init__.pyi"

# Which TypedDict of the stub describes each nested struct of default_options().
NESTED = {
    ("range_filter",): "RangeFilterOptions",
    ("grid",): "LayeredGridOptions",
    ("grid", "regularization"): "CellRegularization",
    ("sampling",): "SamplingOptions",
    ("schedule",): "LayerScheduleOptions",
    ("objective",): "ObjectiveOptions",
    ("backend",): "BackendOptions",
    ("backend", "ceres"): "CeresBackendOptions",
    ("backend", "newton"): "NewtonOptions",
    ("backend", "levenberg_marquardt"): "LevenbergMarquardtOptions",
    ("quality_check",): "QualityCheckOptions",
    ("initial_uncertainty",): "InitialGuessUncertainty",
    ("retry",): "RetryOptions",
}
STUB_TYPES = {bool: {"bool"}, int: {"int"}, float: {"float"}, str: {"str"}, list: {"Sequence[float]"}}


def stub_tree():
    return ast.parse(STUB.read_text())


def stub_classes():
    return {node.name: node for node in stub_tree().body if isinstance(node, ast.ClassDef)}


def typed_dict_fields(node):
    return {
        statement.target.id: ast.unparse(statement.annotation)
        for statement in node.body
        if isinstance(statement, ast.AnnAssign)
    }


def keyword_only(function):
    return [argument.arg for argument in function.args.kwonlyargs]


def function(tree_body, name):
    return next(node for node in tree_body if isinstance(node, ast.FunctionDef) and node.name == name)


def test_stub_typed_dicts_match_default_options():
    classes = stub_classes()
    options = mlndt.default_options()
    assert set(typed_dict_fields(classes["RegistrationOptions"])) == set(options)
    for path, class_name in NESTED.items():
        value = options
        for key in path:
            value = value[key]
        fields = typed_dict_fields(classes[class_name])
        assert set(fields) == set(value), class_name
        for key, default in value.items():
            if isinstance(default, dict):
                assert fields[key] == NESTED[path + (key,)], (class_name, key)
            else:
                assert fields[key] in STUB_TYPES[type(default)], (class_name, key, fields[key])


def test_stub_signatures_list_every_option():
    tree = stub_tree()
    top_level = set(mlndt.default_options())
    register = function(tree.body, "register")
    assert [a.arg for a in register.args.args] == ["reference", "input", "initial", "initial_uncertainty"]
    assert set(keyword_only(register)) == (top_level - {"initial_uncertainty"}) | {"preset"}
    layered_map = stub_classes()["LayeredMap"]
    map_register = function(layered_map.body, "register")
    assert set(keyword_only(map_register)) == (top_level - {"initial_uncertainty", "grid"}) | {"preset"}
    localizer = function(stub_classes()["Localizer"].body, "__init__")
    assert set(keyword_only(localizer)) == (top_level - {"initial_uncertainty", "grid"}) | {"preset"}
    build = function(layered_map.body, "build")
    assert set(keyword_only(build)) == set(mlndt.default_options()["grid"]) | {"preset"}
    odometry_fields = {
        "local_map",
        "keyframes",
        "prediction",
        "deskew",
        "gate_factor",
        "recovery",
        "confirmation",
    }
    odometry = function(stub_classes()["Odometry"].body, "__init__")
    assert set(keyword_only(odometry)) == (top_level - {"initial_uncertainty"}) | {"preset"} | odometry_fields
    run_odometry = function(tree.body, "run_odometry")
    assert set(keyword_only(run_odometry)) == set(keyword_only(odometry))
    assert [a.arg for a in run_odometry.args.args] == ["scans", "stamps", "point_times"]
    filter_range = function(tree.body, "filter_range")
    assert set(keyword_only(filter_range)) == set(mlndt.default_options()["range_filter"])


def test_every_public_name_has_a_stub():
    tree = stub_tree()
    names = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    names |= {node.target.id for node in tree.body if isinstance(node, ast.AnnAssign)}
    assert set(mlndt.__all__) <= names
    # Submodules (mlndt.distributed) are attributes once imported.
    public = {name for name in dir(mlndt) if not name.startswith("_")}
    public -= {name for name in public if isinstance(getattr(mlndt, name), types.ModuleType)}
    assert set(mlndt.__all__) == public | {"__version__"}
    classes = stub_classes()
    for cls in (
        mlndt.RegistrationResult,
        mlndt.LayeredMap,
        mlndt.Localizer,
        mlndt.LocalizationResult,
        mlndt.Odometry,
        mlndt.OdometryResult,
    ):
        body = classes[cls.__name__].body
        stubbed = {node.name for node in body if isinstance(node, ast.FunctionDef) and node.name != "__init__"}
        public = {name for name in dir(cls) if not name.startswith("_")}
        assert public == stubbed, cls.__name__


def test_help_shows_parameters_and_every_option():
    text = pydoc.render_doc(mlndt.register, renderer=pydoc.plaintext)
    assert "register(reference, input, initial=None, initial_uncertainty=None, **options)" in text
    for path, _ in NESTED.items():
        assert f"{path[-1]}: dict ({NESTED[path]})" in text, path

    def all_keys(options):
        for key, value in options.items():
            yield key
            if isinstance(value, dict):
                yield from all_keys(value)

    for key in all_keys(mlndt.default_options()):
        assert f"{key}:" in text, key
    # Defaults are the compiled library's.
    assert f"finest_cell_size_m: float = {mlndt.default_options()['grid']['finest_cell_size_m']}" in text
    map_register = pydoc.render_doc(mlndt.LayeredMap.register, renderer=pydoc.plaintext)
    assert "register(input, initial=None, initial_uncertainty=None, **options)" in map_register
    build = pydoc.render_doc(mlndt.LayeredMap.build, renderer=pydoc.plaintext)
    assert "build(points, num_threads=1, max_memory_gb=8.0, **grid_options)" in build and "min_points_per_cell: int" in build
    for name in mlndt.__all__:
        assert getattr(mlndt, name).__doc__, name


def test_the_build_tree_has_the_stub_and_py_typed():
    package = BUILD_DIR / "python" / "mlndt"
    assert (package / "__init__.pyi").read_text() == STUB.read_text()
    assert (package / "py.typed").exists()


def test_the_package_holds_no_lab():
    # The lab is the separate development module mlndt_lab, never mlndt's.
    package = BUILD_DIR / "python" / "mlndt"
    assert not [p.name for p in package.iterdir() if p.name.startswith(("lab.", "_lab."))]
    assert importlib.util.find_spec("mlndt.lab") is None


def test_generated_docs_and_stub_are_current():
    """docs/options.md, docs/json_schema.md's result tables and this stub's
    RegistrationResult are what mlndt_options generates from the tables."""
    completed = subprocess.run(
        [str(SOURCE_DIR / "scripts" / "check_generated.sh"), str(BUILD_DIR)], capture_output=True, text=True
    )
    assert completed.returncode == 0, completed.stderr
