#!/usr/bin/env bash
# Times this build's mlndt_bench against the one of another revision in the
# same run, so that both see the same machine load:
#   scripts/bench_against.sh REV [mlndt_bench flags...]
# 1. builds REV's mlndt_bench in a detached git worktree under
#    $MLNDT_AGAINST_DIR (default /tmp/mlndt_against), REV's own
#    scripts/build.sh with MLNDT_BUILD_TARGETS=mlndt_bench (ccache makes a
#    rebuild cheap; $MLNDT_AGAINST_CMAKE_ARGS go to its cmake, e.g.
#    -DMLNDT_WITH_PCL=ON);
# 2. runs this tree's build/lab/programs/mlndt_bench ($MLNDT_BENCH overrides) and
#    REV's alternately, $MLNDT_AGAINST_ROUNDS rounds (default 5; the first of
#    a round alternates too), each with the same flags, --repetitions=1
#    unless given, and its own --output_csv;
# 3. prints per row of mlndt_bench's table (set of pairs x method) the
#    median over rounds of each one's time (time med of its run), the median
#    of the per-round ratios old/new, and both success counts.
# Flags are passed to both binaries only if both know them (from their
# --helpfull); the others are dropped with a note on stderr, so that both
# always run the same benchmark. --output_csv, --output_plot and --help* are
# the script's own business and refused. Exit 0 with the table; 1 when a
# build or a run fails; 2 on bad usage.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"

if (($# < 1)) || [[ $1 == -* ]]; then
  echo "usage: $0 REV [mlndt_bench flags...]" >&2
  exit 2
fi
rev="$1"
shift
rounds="${MLNDT_AGAINST_ROUNDS:-5}"
if ! [[ $rounds =~ ^[1-9][0-9]*$ ]]; then
  echo "bench_against: MLNDT_AGAINST_ROUNDS must be a positive integer, not '$rounds'" >&2
  exit 2
fi
new_bench="${MLNDT_BENCH:-$root/build/lab/programs/mlndt_bench}"
if [[ ! -x $new_bench ]]; then
  echo "bench_against: $new_bench not found: build it first (MLNDT_BUILD_TARGETS=mlndt_bench scripts/build.sh)" >&2
  exit 1
fi
if ! sha="$(git -C "$root" rev-parse --verify --quiet "$rev^{commit}")"; then
  echo "bench_against: '$rev' is not a commit of $root" >&2
  exit 2
fi

for arg in "$@"; do
  case "$arg" in
    --output_csv* | -output_csv* | --output_plot* | -output_plot* | --help* | -help*)
      echo "bench_against: $arg is set by the script (or meaningless here)" >&2
      exit 2
      ;;
  esac
done

# 1. REV's build.
base="${MLNDT_AGAINST_DIR:-/tmp/mlndt_against}"
tree="$base/${sha:0:12}"
mkdir -p "$base"
if [[ ! -d $tree ]]; then
  git -C "$root" worktree add --detach "$tree" "$sha" > /dev/null 2>&1 || {
    echo "bench_against: cannot make a worktree of $sha at $tree" >&2
    exit 1
  }
fi
echo "bench_against: building mlndt_bench of $rev (${sha:0:12}) in $tree/build (log in $tree/build.log)" >&2
# shellcheck disable=SC2086  # The cmake arguments are a list.
if ! (cd "$tree" && MLNDT_BUILD_TARGETS=mlndt_bench scripts/build.sh ${MLNDT_AGAINST_CMAKE_ARGS:-} > /dev/null); then
  echo "bench_against: building $rev failed; the end of $tree/build.log:" >&2
  tail -20 "$tree/build.log" >&2
  exit 1
fi
old_bench="$tree/build/lab/programs/mlndt_bench"
# Revisions before the lab's drivers moved to lab/programs/ built it in tools/.
[[ -x $old_bench ]] || old_bench="$tree/build/tools/mlndt_bench"

# 2. The flags both know.
flag_names() { "$1" --helpfull 2>&1 | sed -nE 's/^ +-([a-z0-9_]+) \(.*/\1/p' | sort -u; }
common="$(comm -12 <(flag_names "$new_bench") <(flag_names "$old_bench"))"
args=()
repetitions_given=0
for arg in "$@"; do
  name="${arg#--}"
  name="${name#-}"
  name="${name%%=*}"
  base_name="$name"
  if ! grep -qx "$name" <<< "$common" && [[ $name == no* ]]; then
    base_name="${name#no}"  # --noflag of a boolean flag.
  fi
  if grep -qx "$base_name" <<< "$common"; then
    args+=("$arg")
    [[ $base_name == repetitions ]] && repetitions_given=1
  else
    echo "bench_against: dropping $arg (not a flag of both binaries)" >&2
  fi
done
((repetitions_given)) || args+=(--repetitions=1)

out="$(mktemp -d "${TMPDIR:-/tmp}/bench_against.XXXXXX")"
run() {  # run NAME BINARY ROUND
  local log="$out/$1_$3.log"
  if ! "$2" "${args[@]}" --output_csv="$out/$1_$3.csv" > "$log" 2>&1; then
    echo "bench_against: the $1 mlndt_bench failed in round $3 ($2 ${args[*]}):" >&2
    tail -20 "$log" >&2
    exit 1
  fi
}
echo "bench_against: $rounds round(s) of: mlndt_bench ${args[*]}" >&2
for ((r = 1; r <= rounds; ++r)); do
  if ((r % 2)); then
    run new "$new_bench" "$r"
    run old "$old_bench" "$r"
  else
    run old "$old_bench" "$r"
    run new "$new_bench" "$r"
  fi
  echo "bench_against: round $r/$rounds done" >&2
done

# 3. The table.
/usr/bin/python3 "$root/scripts/bench_against_table.py" "$out" "$rounds" "$rev (${sha:0:12})"
echo "bench_against: runs and logs in $out" >&2
