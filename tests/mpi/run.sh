#!/usr/bin/env bash
# Distributed runs (make test-mpi): every decomposition example on 2 processes against the
# same command on 1 process (the serial path, operators::gmres), field by field within 1e-6
# of each column's size (both stop at a relative residual of 1e-8 or below; the fields
# differ by the interface problem's conditioning times that: measured 3e-11 on the joint);
# then the errors: a one-body file on 2 processes (exit 2), a subdomain left free to move
# (exit 3 from the process that owns it, which ends the others), nothing written by either.
set -euo pipefail
binary=$(realpath "$1")
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mpi=(mpirun -n 2 --oversubscribe)
export OMP_NUM_THREADS=1
failed=0
for example in dd_bonded_joint dd_fibre_composite dd_strips_4 dd_two_layer_tube_axisymmetric; do
  "$binary" run "$root/examples/$example.toml" -o "$work/$example.1" -q
  "${mpi[@]}" "$binary" run "$root/examples/$example.toml" -o "$work/$example.2" -q
  grep -q '"processes": 2' "$work/$example.2/summary.json" || { echo "test-mpi: $example: not run on 2 processes"; failed=1; }
  files=()
  for f in "$work/$example.1"/*_boundary.csv "$work/$example.1"/*_interior.csv; do
    [ -e "$f" ] && files+=("$(basename "$f")")
  done
  python3 "$root/tests/mpi/compare_runs.py" "$work/$example.1" "$work/$example.2" 1e-6 "${files[@]}" || failed=1
done

expect_failure() {  # expected exit code, message fragment, problem file
  local code=0
  "${mpi[@]}" "$binary" run "$3" -o "$work/failed" -q > "$work/log" 2>&1 || code=$?
  if [ "$code" -ne "$1" ] || ! grep -q "$2" "$work/log" || [ -e "$work/failed" ]; then
    echo "test-mpi: $3: exit $code (expected $1), output folder $( [ -e "$work/failed" ] && echo written || echo absent)"
    cat "$work/log"
    failed=1
  else
    echo "test-mpi: $(basename "$3"): exit $code as expected"
  fi
}
expect_failure 2 "serve one body of several regions" "$root/examples/plate_hole.toml"
grep -v displacement_nodes "$root/examples/dd_strips_2.toml" | sed 's/^method = .*/method = "hybrid"/' > "$work/hybrid.toml"
expect_failure 3 "is free to move" "$work/hybrid.toml"

if [ "$failed" -ne 0 ]; then echo "test-mpi: FAILED"; exit 1; fi
echo "test-mpi: passed"
