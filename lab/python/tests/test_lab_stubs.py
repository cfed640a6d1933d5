"""The stub of the lab's module mlndt_lab (lab/python/mlndt_lab/__init__.pyi)
names every public name and method, and the build tree has it."""

import ast

from conftest import BUILD_DIR, SOURCE_DIR, import_lab


def test_lab_stub_names_every_public_name():
    lab = import_lab()
    assert lab.__file__ == str(BUILD_DIR / "python" / "mlndt_lab" / "__init__.py")
    stub = SOURCE_DIR / "lab" / "python" / "mlndt_lab" / "__init__.pyi"
    assert (BUILD_DIR / "python" / "mlndt_lab" / "__init__.pyi").read_text() == stub.read_text()
    tree = ast.parse(stub.read_text())
    names = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    assert set(lab.__all__) - {"__version__"} <= names
    classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
    for cls in (lab.PairResult, lab.ScanStore, lab.RosBag, lab.BagScan):
        assert cls.__module__ == "mlndt_lab"
        stubbed = {node.name for node in classes[cls.__name__].body if isinstance(node, ast.FunctionDef)}
        assert {name for name in dir(cls) if not name.startswith("_")} <= stubbed, cls.__name__
