"""The module from an install prefix: cmake --install puts the package under
<prefix>/lib/python3/dist-packages/mlndt (MLNDT_PYTHON_INSTALL_DIR), and the
Debian interpreter imports it from there with PYTHONPATH and nothing of the
build tree."""

import json
import os
import shutil
import subprocess

import pytest

import mlndt
from conftest import BUILD_DIR, KOIDE3_INPUT, KOIDE3_REFERENCE, PYTHON

SCRIPT = f"""
import importlib.util, json, mlndt, mlndt.distributed
assert importlib.util.find_spec('mlndt_lab') is None
reference = mlndt.read_cloud({str(KOIDE3_REFERENCE)!r})
input = mlndt.read_cloud({str(KOIDE3_INPUT)!r})
result = mlndt.register(reference, input)
print(json.dumps({{"file": mlndt.__file__, "version": mlndt.__version__,
                  "pose": result.reference_from_input.tolist(), "termination": result.termination_type}}))
"""


def test_installed_package_imports_and_registers(tmp_path, koide3_result):
    cmake = shutil.which("cmake")
    if cmake is None:
        pytest.fail("cmake is not on PATH")
    prefix = tmp_path / "prefix"
    install = subprocess.run(
        [cmake, "--install", str(BUILD_DIR), "--prefix", str(prefix), "--component", "python"],
        capture_output=True,
        text=True,
    )
    assert install.returncode == 0, install.stdout + install.stderr
    package = prefix / "lib" / "python3" / "dist-packages" / "mlndt"
    names = sorted(p.name for p in package.iterdir())
    assert "__init__.py" in names and "__init__.pyi" in names and "py.typed" in names
    assert any(name.startswith("_mlndt.") and name.endswith(".so") for name in names), names
    assert "distributed.py" in names
    # The product only: the lab's module mlndt_lab is not installed.
    assert not [name for name in names if name.startswith(("lab.", "_lab."))], names
    assert sorted(p.name for p in package.parent.iterdir()) == ["mlndt"]

    environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    environment["PYTHONPATH"] = str(package.parent)
    completed = subprocess.run(
        [PYTHON, "-c", SCRIPT], capture_output=True, text=True, env=environment, cwd=str(tmp_path)
    )
    assert completed.returncode == 0, completed.stderr
    reported = json.loads(completed.stdout)
    assert reported["file"] == str(package / "__init__.py")
    assert reported["version"] == mlndt.__version__
    assert reported["termination"] == "CONVERGENCE"
    assert reported["pose"] == koide3_result.reference_from_input.tolist()


def test_build_tree_package_is_the_one_under_test():
    assert mlndt.__file__ == str(BUILD_DIR / "python" / "mlndt" / "__init__.py")
