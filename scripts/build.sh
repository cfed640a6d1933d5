#!/usr/bin/env bash
# Configures and builds mlndt (Release) in build/. Extra arguments go to cmake.
# Uses ccache when it is installed (rebuilds after a branch switch are cheap).
# MLNDT_BUILD_TARGETS="t1 t2" builds only those targets (and what they need);
# unset, everything is built.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache > /dev/null; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(pwd)}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
targets=()
for target in ${MLNDT_BUILD_TARGETS:-}; do
  targets+=(--target "$target")
done
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build "${targets[@]}" -j"$(nproc)" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
echo "build: ok${MLNDT_BUILD_TARGETS:+ (${MLNDT_BUILD_TARGETS})} (log in build.log)"
