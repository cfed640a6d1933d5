#!/usr/bin/env bash
# Fails when a tracked C++ file differs from the repo's .clang-format
# (clang-format 14, Debian 12). Fix with: clang-format -i FILES.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
mapfile -t files < <(git ls-files '*.h' '*.cc' '*.cpp' '*.hpp')
if ! clang-format --dry-run -Werror "${files[@]}" 2> build/format.log; then
  grep -E "^[^ ].*error:" build/format.log | cut -d: -f1 | sort -u | sed 's/^/  needs clang-format: /'
  echo "check_format: run clang-format -i on the files above" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files clean"
