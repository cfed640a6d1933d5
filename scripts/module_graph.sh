#!/usr/bin/env bash
# Prints the include graph between mlndt/'s module folders: one line
# "from -> to: N" per pair, N the number of #include lines (a folder's
# internal/ counts as the folder; the umbrella header mlndt/mlndt.h is left
# out). CMakeLists.txt groups the folders into layers from this graph
# (mlndt_add_layer); scripts/check_boundaries.sh enforces the layers.
set -euo pipefail
cd "$(dirname "$0")/.."
grep -rnoE '^#include [<"]mlndt/[a-z_]+/' mlndt/*/ --include=*.h --include=*.cc |
  sed -E 's#^mlndt/([a-z_]+)/[^:]*:[0-9]+:\#include [<"]mlndt/([a-z_]+)/$#\1 \2#' |
  awk '$1 != $2 { n[$1 " -> " $2]++ } END { for (k in n) print k ": " n[k] }' | sort
