#!/usr/bin/env bash
# The abrasive-flow scene's removed mass over seeded grain starts (issue 51, README.md here):
# seeds 1-4 jitter each grain's start by up to dp/2; local and non-local damage (l = 1 um) of the
# PMMA; the first 0.5 us (the launched grains' first impacts). Usage: run_afm.sh DP NAME
#   e.g. run_afm.sh 5e-7 afm_dp0.5
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../../.."
out="$root/out/erosion_convergence/$2"
"$root/build/release/monosph" study "$root/cases/abrasive_flow_machining/scene.yaml" \
  --vary variables.nonlocal=0,1e-6 --vary variables.seed=1,2,3,4 --repeat variables.seed \
  --jobs 1 --threads 2 --out "$out" --set dp="$1" --set end_time=5e-7 --set output.every=0 || true
cp "$out/study.csv" "$here/$2_study.csv"
cp "$out/study_stats.csv" "$here/$2_stats.csv"
