#!/bin/bash
# Run from the repository root; BUILD (default build) and RUNS (default /tmp/tilt/runs) may be set.
# run.sh SETS NAME [flags...]: mlndt_suite from the exact pose with 0.1 m / 2° on every set in SETS
sets=$1; name=$2; shift 2
ds=$(cd $sets && ls -d */ | tr -d / | paste -sd, -)
${BUILD:-build}/lab/programs/mlndt_suite --data_dir=$sets --datasets=$ds --starts=prior --prior_uncertainty=0.1,2 --output_dir=${RUNS:-/tmp/tilt/runs}/$name "$@" > ${RUNS:-/tmp/tilt/runs}_$name.log 2>&1
python3 lab/records/tilt_scripts/tilt_stats.py ${RUNS:-/tmp/tilt/runs}/$name/runs.csv
