#!/usr/bin/env bash
# One controlled experiment of lab/records/bias.md: mlndt_suite on the sets in
# SETS (made by mlndt_simulate) from the given starts, with extra registration
# flags; writes OUT/LABEL/runs.csv and prints the along-track bias.
#
#   run_variant.sh SETS OUT LABEL STARTS DATASET_GLOB [registration flags...]
#   e.g. run_variant.sh /tmp/wt_bias/sets /tmp/wt_bias/runs all_pts prior \
#            'hdl64_*' --sampling=all
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../../.." && pwd)"
sets=$1 out=$2 label=$3 starts=$4 glob=$5
shift 5
datasets=$(cd "$sets" && ls -d $glob | paste -sd, -)
mkdir -p "$out/$label"
"$repo/build/lab/programs/mlndt_suite" --data_dir="$sets" --datasets="$datasets" \
  --starts="$starts" --output_dir="$out/$label" "$@" > "$out/$label/log.txt" 2>&1
python3 "$here/along_track.py" "$sets" "$out/$label/runs.csv"
