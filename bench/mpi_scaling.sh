#!/usr/bin/env bash
# Distributed runs against one process (needs a build with -DBEMCONTACT_WITH_MPI=ON, e.g.
# after `make test-mpi`): balanced strips (scripts/strips_toml.py) and a fibre composite
# (one large subdomain, scripts/fibre_composite_toml.py), each on 1 process with 1 and 2
# threads and on 2 processes with 1 thread; wall time and the phases of summary.json.
# Usage: bench/mpi_scaling.sh [BINARY] (default build/bemcontact)
set -euo pipefail
binary=$(realpath "${1:-build/bemcontact}")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
python3 "$root/scripts/strips_toml.py" 8 400 200 > "$work/strips.toml"
python3 "$root/scripts/fibre_composite_toml.py" 6 > "$work/fibres.toml"
phases() {
  python3 - "$1" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
d = s["results"]["decomposition"]
t = d["timings"]
print("  ".join(f"{p['name']} {p['seconds']:.2f}" for p in t["phases"]), f"| iterations {d['gmres']['iterations']}")
PY
}
for problem in strips fibres; do
  for run in "1 1" "1 2" "2 1"; do
    set -- $run
    start=$(date +%s.%N)
    OMP_NUM_THREADS=$2 mpirun -n "$1" --oversubscribe --bind-to none "$binary" run "$work/$problem.toml" -o "$work/out" -q
    end=$(date +%s.%N)
    printf '%-7s processes %s threads %s: %6.2f s  ' "$problem" "$1" "$2" "$(echo "$end - $start" | bc)"
    phases "$work/out/summary.json"
  done
done
