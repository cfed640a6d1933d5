#!/usr/bin/env bash
# Fails when an include crosses a module boundary the wrong way. The
# dependency order is mlndt <- lab <- tools (README, "Code layout"):
#   mlndt/   the installed library: no lab/, tools/, gflags or nlohmann_json;
#            inside it, its layers (CMakeLists.txt's mlndt_add_layer lines,
#            read here: core <- registration <- pipeline) include only their
#            own folders and those of the layers they declare. The build
#            checks the same order on the calls (cmake/mlndt_layers.cmake);
#            this check also sees a wrong-way include of inline code;
#   lab/     evaluation and experiments: no tools/ and no gflags; its
#            programs (lab/programs/, mains built but never installed)
#            sit on top of both and may use the command-line layer;
#   python/         the product's Python module (bindings, package, tests):
#                   no lab/ or tools/ include, no import of the lab's module;
#   lab/python/     the lab's development module mlndt_lab (never
#                   installed): no tools/.
set -euo pipefail
cd "$(dirname "$0")/.."

status=0
forbid() {
  local dir="$1" pattern="$2" why="$3" hits
  hits="$(grep -rnE "^#include [<\"]($pattern)" "$dir" --include=*.h --include=*.cc "${@:4}" || true)"
  if [[ -n $hits ]]; then
    echo "check_boundaries: $dir must not include $why:" >&2
    echo "$hits" >&2
    status=1
  fi
}

forbid mlndt 'lab/|tools/' "the lab or the tools (mlndt <- lab <- tools)"
# The library's layers: "name folders... [DEPENDS layers...]" per line.
declare -A layer_folders layer_depends
layers=()
while read -r name rest; do
  layers+=("$name")
  layer_folders[$name]="${rest%% DEPENDS*}"
  [[ $rest == *" DEPENDS "* ]] && layer_depends[$name]="${rest#* DEPENDS }"
done < <(sed -nE 's/^mlndt_add_layer\(([a-z_]+) FOLDERS (.*)\)$/\1 \2/p' CMakeLists.txt)
if ((${#layers[@]} == 0)); then
  echo "check_boundaries: no mlndt_add_layer(NAME FOLDERS ...) line in CMakeLists.txt" >&2
  status=1
fi
for name in "${layers[@]}"; do
  allowed=" ${layer_folders[$name]} "
  for below in ${layer_depends[$name]:-}; do allowed+="${layer_folders[$below]} "; done
  above=()
  for other in "${layers[@]}"; do
    for folder in ${layer_folders[$other]}; do
      [[ $allowed == *" $folder "* ]] || above+=("$folder")
    done
  done
  if ((${#above[@]} > 0)); then
    pattern="mlndt/($(IFS='|'; echo "${above[*]}"))/"
    for folder in ${layer_folders[$name]}; do
      forbid "mlndt/$folder" "$pattern" "a layer above $name (CMakeLists.txt, mlndt_add_layer)"
    done
  fi
done
forbid mlndt 'gflags/|nlohmann/' "gflags or nlohmann_json (the installed package needs neither)"
forbid lab 'tools/' "the tools (mlndt <- lab <- tools)" --exclude-dir=programs
forbid lab 'gflags/' "gflags (flags belong to tools/ and the lab's programs)" --exclude-dir=programs
forbid python 'lab/|tools/' "the lab or the tools (python/ is the product: mlndt binds the library only)"
forbid lab/python 'tools/' "the tools (mlndt_lab binds the lab)"
forbid mlndt 'integrations/' "an integration (integrations/ builds on the library)"
forbid lab 'integrations/' "an integration (integrations/ builds on the library)"
forbid tools 'integrations/' "an integration (integrations/ builds on the library)"
forbid integrations/ros/core '(ros|rclcpp|tf2_ros|tf2|sensor_msgs|nav_msgs|geometry_msgs|diagnostic_msgs)/' "a middleware header (the node core is middleware-free)"
# Python: an import statement or importlib.import_module naming the lab's
# module (mlndt_lab, its extension _lab, the old submodule mlndt.lab) or a
# path into lab/ (sys.path, spec_from_file_location).
hits="$(grep -rnE --include=*.py --include=*.pyi \
  -e '^\s*(import|from)\s.*\b(mlndt_lab|_lab|lab)\b' \
  -e 'import_module\(.*\b(mlndt_lab|_lab|lab)\b' \
  -e '["/]lab/' python || true)"
if [[ -n $hits ]]; then
  echo "check_boundaries: python/ (the product) must not import the lab:" >&2
  echo "$hits" >&2
  status=1
fi

if ((status == 0)); then
  echo "check_boundaries: mlndt's layers ${layers[*]}, mlndt <- lab <- tools, python/ -> mlndt, lab/python -> lab: ok"
fi
exit $status
