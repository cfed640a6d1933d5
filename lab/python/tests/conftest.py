"""Fixtures of the lab's Python tests (the development module mlndt_lab).

The product's tests (python/tests/conftest.py) hold the paths, fixtures and
helpers; this file reuses them (loaded under another module name, since both
are "conftest") and adds import_lab(). ctest runs each file as the product's
(lab/python/CMakeLists.txt); by hand, from the source tree:

    PYTHONPATH=build/python /usr/bin/python3 -m pytest lab/python/tests
"""

import importlib
import importlib.util
import os
import sys
from pathlib import Path

import pytest

_PRODUCT_CONFTEST = Path(__file__).resolve().parents[3] / "python" / "tests" / "conftest.py"
_spec = importlib.util.spec_from_file_location("mlndt_product_conftest", _PRODUCT_CONFTEST)
_product = importlib.util.module_from_spec(_spec)
sys.modules[_spec.name] = _product
_spec.loader.exec_module(_product)

from mlndt_product_conftest import *  # noqa: E402,F401,F403 (paths, fixtures, pytest_sessionfinish)


def import_lab():
    """The lab's module mlndt_lab, which the development build makes beside
    mlndt (CMake option MLNDT_BUILD_PYTHON_LAB; never installed, not in the
    wheel). Skips the calling test file, saying why, when this build has no
    lab module; a build that says it made one (ctest passes the option) must
    import it."""
    built = os.environ.get("MLNDT_BUILD_PYTHON_LAB")
    if built is None:
        missing = importlib.util.find_spec("mlndt_lab") is None
    else:
        missing = built.upper() in ("", "0", "OFF", "FALSE", "NO", "N")
    if missing:
        pytest.skip(
            "the lab's module mlndt_lab is not built (a development build makes it: "
            "-DMLNDT_BUILD_PYTHON_LAB=ON, as scripts/test.sh configures)",
            allow_module_level=True,
        )
    return importlib.import_module("mlndt_lab")
