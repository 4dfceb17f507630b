#!/usr/bin/env bash
# The erosion convergence study of issue 51 (README.md here): seeded impacts of the erosion map
# (cases/erosion_map) at 30 and 90 deg, 150 and 300 m/s, local and non-local damage (l = 20 um),
# at dp = 10, 5 and 2.5 um. Usage: run.sh DP NONLOCAL_VALUES SPEEDS SEEDS NAME
#   e.g. run.sh 1e-5 0,2e-5 150,300 1,2,3,4,5,6,7,8 dp10
# Writes out/erosion_convergence/NAME and copies study.csv and study_stats.csv here as NAME_*.csv.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../../.."
out="$root/out/erosion_convergence/$5"
"$root/build/release/monosph" study "$root/cases/erosion_map/scene.yaml" \
  --vary variables.angle=30,90 --vary variables.speed="$3" --vary variables.nonlocal="$2" \
  --vary variables.seed="$4" --repeat variables.seed --jobs 1 --threads 2 --out "$out" \
  --set dp="$1" --set end_time=2e-6 --set output.every=0 || true
cp "$out/study.csv" "$here/$5_study.csv"
cp "$out/study_stats.csv" "$here/$5_stats.csv"
