#!/usr/bin/env bash
# Checks mlndt::pcl (integrations/pcl/, docs/pcl.md) end to end:
#  1. configures build-pcl/ with -DMLNDT_WITH_PCL=ON (tools, benchmarks and
#     Python off) and builds the library and the adapter's tests only;
#  2. runs the tests (ctest -R '^pcl/');
#  3. installs to a fresh prefix (build-pcl/check_pcl/install) and builds
#     examples/pcl_ndt against it as an outside project with
#     find_package(mlndt COMPONENTS pcl): PCL's NDT tutorial with
#     pcl::NormalDistributionsTransform and with only the type changed to
#     mlndt::pcl::MultiLayerNdt;
#  4. runs both on data/room; the mlndt one must report convergence and land
#     within 5 cm of the pair's reference pose.
# Needs libpcl-dev (scripts/install_deps.sh --with-pcl). Uses ccache when it
# is installed. Log: build-pcl/check_pcl.log.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
log="$root/build-pcl/check_pcl.log"
launcher=()
if command -v ccache > /dev/null; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# The install prefix and the outside build, under build-pcl/ (fresh each run;
# a fixed path inside the tree lets ccache reuse the examples' objects).
prefix="$root/build-pcl/check_pcl"
rm -rf "$prefix"
mkdir -p "$prefix"
step() { echo "check_pcl: $*"; }
run() { "$@" >> "$log" 2>&1 || { tail -40 "$log"; echo "check_pcl: failed: $*" >&2; exit 1; }; }
: > "$log"

step "configure and build build-pcl/ (mlndt, mlndt_pcl_test)"
run cmake -S . -B build-pcl -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
  -DMLNDT_WITH_PCL=ON -DMLNDT_BUILD_TESTS=ON -DMLNDT_BUILD_TOOLS=OFF \
  -DMLNDT_BUILD_BENCHMARKS=OFF -DMLNDT_BUILD_PYTHON=OFF
run cmake --build build-pcl --target mlndt mlndt_pcl_test -j"$(nproc)"

step "tests"
ctest --test-dir build-pcl -R '^pcl/' --output-on-failure -j"$(nproc)" \
  --timeout 120 >> "$log" 2>&1 || { grep -E "tests passed|Failed|\*\*\*" "$log" | tail -30; exit 1; }
grep -E "tests passed" "$log" | tail -1

step "install to build-pcl/check_pcl/install; build examples/pcl_ndt against it"
run cmake --install build-pcl --prefix "$prefix/install"
run cmake -S examples/pcl_ndt -B "$prefix/example" -DCMAKE_BUILD_TYPE=Release \
  "${launcher[@]}" -DCMAKE_PREFIX_PATH="$prefix/install"
run cmake --build "$prefix/example" --target pcl_ndt_tutorial mlndt_ndt_tutorial \
  -j"$(nproc)"

step "PCL's NDT tutorial on data/room, with each type"
for program in pcl_ndt_tutorial mlndt_ndt_tutorial; do
  status=0
  "$prefix/example/$program" data/room "$prefix/$program.pcd" \
    > "$prefix/$program.out" 2>&1 || status=$?
  echo "  $program: exit $status, $(grep 'has converged' "$prefix/$program.out")"
  if [[ $program == mlndt_ndt_tutorial && $status -ne 0 ]]; then
    cat "$prefix/$program.out"
    echo "check_pcl: $program did not converge" >&2
    exit 1
  fi
done
# The last four lines of each output: the final transformation.
/usr/bin/python3 - "$prefix" data/room/reference_pairs.json << 'EOF'
import json, math, sys
prefix, reference_file = sys.argv[1], sys.argv[2]
ref = json.load(open(reference_file))["1_2"]["reference_from_input"]
ref_t = [ref[3], ref[7], ref[11]]
status = 0
for program in ("pcl_ndt_tutorial", "mlndt_ndt_tutorial"):
    rows = [l.split() for l in open(f"{prefix}/{program}.out").read().splitlines()[-4:]]
    t = [float(rows[i][3]) for i in range(3)]
    error = math.dist(t, ref_t)
    print(f"  {program}: {error:.3f} m from the reference translation")
    if program == "mlndt_ndt_tutorial" and error > 0.05:
        print("check_pcl: mlndt_ndt_tutorial is more than 5 cm off", file=sys.stderr)
        status = 1
sys.exit(status)
EOF
step "ok"
