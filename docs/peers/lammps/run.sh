#!/bin/sh
# Run the MACHDYN Taylor bar deck serially and print particle-steps/s from LAMMPS's own timing.
#   docs/peers/lammps/run.sh [n] [lmp binary] [steps]
#   n      particles across the bar diameter (default 29: 95,700 particles; 10: 4050)
#   lmp    a serial LAMMPS binary with MACHDYN (default /tmp/lmpsrc/build/lmp; see README.md)
#   steps  time steps (default 300)
# The log is written to log.taylor_bar.n<n>.<pid> in the current directory (kept).
set -eu
n=${1:-29}
lmp=${2:-/tmp/lmpsrc/build/lmp}
steps=${3:-300}
deck=$(cd "$(dirname "$0")" && pwd)/taylor_bar.in
log=log.taylor_bar.n$n.$$
echo "uptime before run: $(uptime)"
OMP_NUM_THREADS=1 "$lmp" -in "$deck" -var n "$n" -var nsteps "$steps" -log "$log" -screen none > /dev/null
awk '
  /^Loop time of/ { loop = $4; procs = $6; nsteps = $9; atoms = $12 }
  /average # of neighbors\/particle in group tlsph/ { nref = $NF }
  /^Step / { for (i = 1; i <= NF; i++) if ($i == "c_nnave") col = i; inthermo = 1; next }
  /^Loop time of/ { inthermo = 0 }
  inthermo && col && $1 ~ /^[0-9]+$/ { nn = $col }
  /^(Pair|Neigh|Comm|Output|Modify) +\|/ { sect[$1] = $3; pct[$1] = $NF }
  /^Other +\|/ { sect[$1] = $4; pct[$1] = $NF }
  /% CPU use/ { cpu = $1 }
  END {
    if (loop == "") { print "no Loop time line in the log" > "/dev/stderr"; exit 1 }
    ps = atoms * nsteps / loop
    printf "atoms %d  steps %d  procs %d  loop time %.3f s  (%s CPU use)\n", atoms, nsteps, procs, loop, cpu
    printf "particle-steps/s %.4g\n", ps
    printf "mean neighbours (compute smd/tlsph/num/neighs, last thermo) %.3f\n", nn
    printf "pair interactions/s (particle-steps/s x mean neighbours) %.4g\n", ps * nn
    printf "breakdown [s (%%)]:"
    n = split("Pair Neigh Comm Output Modify Other", k, " ")
    for (i = 1; i <= n; i++) printf " %s %s (%s%%)", k[i], sect[k[i]], pct[k[i]]
    printf "\n"
  }' "$log"
echo "log: $log"
