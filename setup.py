"""setuptools' side of pip install . (pyproject.toml has the metadata).

build_ext runs the project's CMake: it configures a build of the library and
its extension only (no lab, tests, tools or benchmarks; no gflags, GoogleTest
or nlohmann_json needed) for the interpreter running pip, builds the target
mlndt_python (mlndt._mlndt) and copies it into the package. The wheel is the
product: the lab's module mlndt_lab is a development build's
(MLNDT_BUILD_PYTHON_LAB, scripts/test.sh), not pip's. Extra CMake arguments: MLNDT_CMAKE_ARGS; parallel jobs:
CMAKE_BUILD_PARALLEL_LEVEL (default: all cores). ccache is used when
installed.
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(mlndt VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    """An extension module built by the CMake target `target`."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def run(self):
        # One level below the source like scripts/build.sh's build/: with
        # CCACHE_BASEDIR the compiler lines are then the same, and ccache
        # serves the objects a developer build compiled.
        build_dir = ROOT / "build-pip"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DMLNDT_BUILD_TESTS=OFF", "-DMLNDT_BUILD_TOOLS=OFF", "-DMLNDT_BUILD_BENCHMARKS=OFF",
            "-DMLNDT_BUILD_PYTHON=ON", "-DMLNDT_BUILD_PYTHON_LAB=OFF", f"-DPython_EXECUTABLE={sys.executable}",
        ]  # fmt: skip
        env = dict(os.environ)
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            env.setdefault("CCACHE_BASEDIR", str(ROOT))
        configure += shlex.split(os.environ.get("MLNDT_CMAKE_ARGS", ""))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        targets = [ext.target for ext in self.extensions]
        subprocess.run(configure, check=True, env=env)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", *targets, "-j", jobs], check=True, env=env)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        for ext in self.extensions:
            built = build_dir / "python" / "mlndt" / (ext.name.split(".")[-1] + suffix)
            if not built.exists():
                raise RuntimeError(f"{built}: CMake did not build {ext.name} (target {ext.target})")
            destination = Path(self.get_ext_fullpath(ext.name))
            destination.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(built, destination)


setup(
    version=project_version(),
    ext_modules=[CMakeExtension("mlndt._mlndt", "mlndt_python")],
    cmdclass={"build_ext": CMakeBuild},
    # Not build/: that is the CMake build of scripts/build.sh.
    options={"build": {"build_base": "build-pip/setuptools"}},
)
