#!/usr/bin/env bash
# CI step: pip install from a clean clone, offline, against Debian's packages
# (scripts/install_deps.sh), exactly as the README says:
#   python3 -m venv --system-site-packages v
#   v/bin/pip install --no-build-isolation .
# then imports mlndt and mlndt.distributed from the venv (not from a source or
# build tree), registers the bundled koide3 pair and checks that the wheel is
# the product only: no lab module (mlndt.lab, mlndt_lab) and no lab file. The clone is
# of HEAD: commit what you want checked. PIP_NO_INDEX makes pip fail rather
# than download anything. Prints the timings; the work folder is removed.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir="$(pwd)"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
git clone -q --no-local "$source_dir" "$work/mlndt"
/usr/bin/python3 -m venv --system-site-packages "$work/v"

start=$SECONDS
if ! (cd "$work/mlndt" && PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 \
  "$work/v/bin/pip" install --no-build-isolation .) > "$work/pip.log" 2>&1; then
  tail -40 "$work/pip.log"
  echo "check_pip_install: pip install failed (log above)" >&2
  exit 1
fi
grep -E "^Successfully" "$work/pip.log" || true
echo "check_pip_install: pip install took $((SECONDS - start)) s"

cd "$work"
"$work/v/bin/python" - "$source_dir/data/koide3" "$work/v" << 'PYTHON'
import importlib.util
import sys
from pathlib import Path

import mlndt
import mlndt.distributed

data, venv = Path(sys.argv[1]), Path(sys.argv[2]).resolve()
for module in (mlndt, mlndt.distributed):
    if venv not in Path(module.__file__).resolve().parents:
        sys.exit(f"check_pip_install: {module.__name__} imported from {module.__file__}, not the venv")
lab_files = [p.name for p in Path(mlndt.__file__).parent.iterdir() if "lab" in p.name]
if lab_files or importlib.util.find_spec("mlndt_lab") is not None:
    sys.exit(f"check_pip_install: the wheel ships the lab: {lab_files or 'mlndt_lab'}")
try:
    import mlndt.lab  # noqa: F401
    sys.exit("check_pip_install: mlndt.lab imports from the installed package")
except ModuleNotFoundError:
    pass
result = mlndt.register(mlndt.read_cloud(data / "251370668.pcd"), mlndt.read_cloud(data / "251371071.pcd"))
if not result.converged:
    sys.exit(f"check_pip_install: the koide3 pair did not converge: {result.message}")
print(f"check_pip_install: mlndt {mlndt.__version__} from {Path(mlndt.__file__).parent}: "
      f"koide3 {result.termination_type}, t = {result.reference_from_input[:3, 3].round(3).tolist()}; "
      f"mlndt.distributed imports; no lab module in the wheel: ok")
PYTHON
