#!/bin/bash
# runcfg.sh BUILD OUT SETSDIR DATASETS [flags...]: one mlndt_suite run over sim sets
build=$1; out=$2; sets=$3; ds=$4; shift 4
$build/tools/mlndt_suite --data_dir=$sets --datasets=$ds --starts=identity,perturbed,prior --perturb=1,20 --prior_uncertainty=0.1,2 --output_dir=$out "$@" > $out.log 2>&1
