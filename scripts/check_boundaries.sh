#!/usr/bin/env bash
# Fails when an include crosses a module boundary the wrong way. The
# dependency order is mlndt <- lab <- tools (README, "Modules"):
#   mlndt/   the installed library: no lab/, tools/, gflags or nlohmann_json;
#   lab/     evaluation and experiments: no tools/ and no gflags;
#   python/src      the bindings of the library (mlndt._mlndt): no lab/
#                   and no tools/;
#   python/mlndt    the installed package: does not import the lab's module;
#   python/lab_src  the bindings of the lab (the development module
#                   mlndt_lab, never installed): no tools/.
set -euo pipefail
cd "$(dirname "$0")/.."

status=0
forbid() {
  local dir="$1" pattern="$2" why="$3" hits
  hits="$(grep -rnE "^#include [<\"]($pattern)" "$dir" --include=*.h --include=*.cc || true)"
  if [[ -n $hits ]]; then
    echo "check_boundaries: $dir must not include $why:" >&2
    echo "$hits" >&2
    status=1
  fi
}

forbid mlndt 'lab/|tools/' "the lab or the tools (mlndt <- lab <- tools)"
forbid mlndt 'gflags/|nlohmann/' "gflags or nlohmann_json (the installed package needs neither)"
forbid lab 'tools/' "the tools (mlndt <- lab <- tools)"
forbid lab 'gflags/' "gflags (flags belong to tools/)"
forbid python/src 'lab/|tools/' "the lab or the tools (mlndt._mlndt binds the library only)"
forbid python/lab_src 'tools/' "the tools (mlndt_lab binds the lab)"
hits="$(grep -rnE '^\s*(import|from)\s.*\b(mlndt_lab|_lab|lab)\b' python/mlndt || true)"
if [[ -n $hits ]]; then
  echo "check_boundaries: python/mlndt (the installed package) must not import the lab:" >&2
  echo "$hits" >&2
  status=1
fi

if ((status == 0)); then
  echo "check_boundaries: mlndt <- lab <- tools, python/src and python/mlndt -> mlndt, python/lab_src -> lab: ok"
fi
exit $status
