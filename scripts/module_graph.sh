#!/usr/bin/env bash
# Prints the dependency graph between mlndt/'s module folders, one line
# "from -> to: N" per pair:
#   scripts/module_graph.sh               N #include lines (a folder's
#                                         internal/ counts as the folder; the
#                                         umbrella mlndt/mlndt.h is left out);
#   scripts/module_graph.sh --link BUILD  N references from one folder's
#                                         objects to symbols another folder's
#                                         objects define (not weak ones:
#                                         inline and template code), from
#                                         a built BUILD folder's layers (nm).
# CMakeLists.txt groups the folders into layers from this graph
# (mlndt_add_layer); scripts/check_boundaries.sh and the build enforce them.
set -euo pipefail
cd "$(dirname "$0")/.."

count() { awk '$1 != $2 { n[$1 " -> " $2]++ } END { for (k in n) print k ": " n[k] }' | sort; }

if [[ ${1:-} != --link ]]; then
  grep -rnoE '^#include [<"]mlndt/[a-z_]+/' mlndt/*/ --include=*.h --include=*.cc |
    sed -E 's#^mlndt/([a-z_]+)/[^:]*:[0-9]+:\#include [<"]mlndt/([a-z_]+)/$#\1 \2#' | count
  exit 0
fi
build="${2:?usage: scripts/module_graph.sh --link BUILD}"
# "D folder symbol" for each definition, "U folder symbol" for each use.
find "$build"/CMakeFiles/mlndt_*.dir/mlndt -name '*.o' | sort | while read -r object; do
  folder="$(sed -E 's#.*/mlndt/([a-z_]+)/.*#\1#' <<< "$object")"
  nm --defined-only "$object" | awk -v f="$folder" '$2 ~ /^[TDBR]$/ { print "D", f, $3 }'
  nm -u "$object" | awk -v f="$folder" '{ print "U", f, $2 }'
done | awk '$1 == "D" && !($3 in owner) { owner[$3] = $2 }
            $1 == "U" { use[++n] = $2 " " $3 }
            END { for (i = 1; i <= n; i++) { split(use[i], u, " ");
                    if (u[2] in owner) print u[1], owner[u[2]] } }' | count
