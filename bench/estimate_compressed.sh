#!/usr/bin/env bash
# The estimate printed before a compressed run against the run itself: one-body examples
# with every element count times n and operator = "compressed", without interior points.
# Prints unknowns, wall time and peak memory (RSS, /usr/bin/time), the estimate and their
# ratios (estimate / measured), per case and size; the calibration of the compressed
# estimate (src/driver/resource_check.cpp, docs/problem-file.md, Limits) was made from
# this table. Usage: bench/estimate_compressed.sh [build dir] [full] (default build; the
# quick set takes ~40 s, full, 4k to 40k unknowns, ~6 min). One run at a time, on a machine
# with a core free: the compressed path runs on one thread.
set -euo pipefail
build=${1:-build}
full=${2:-}
exe=$(realpath "$build/bemcontact")
examples=$(realpath "$(dirname "$0")/../examples")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# make NAME EXAMPLE [interpolation]: element counts times the parameter n.
make() {
  sed -e 's/^\[parameters\]/[parameters]\nn = 1/' -e 's/^elements = \([0-9]*\)/elements = "n*\1"/' \
      -e '/^\[interior\]/,$d' "$examples/$2" > "$work/$1.toml"
  grep -q '^\[parameters\]' "$examples/$2" || sed -i '0,/^\[material\]/s//[parameters]\nn = 1\n\n[material]/' "$work/$1.toml"
  [ -n "${3:-}" ] && sed -i "s/^interpolation = \"linear\"/interpolation = \"$3\"/" "$work/$1.toml"
  printf '\n[solver]\noperator = "compressed"\n' >> "$work/$1.toml"
}
make plate plate_hole.toml
make plate_quadratic plate_hole.toml quadratic
make ring thick_ring_plane_strain.toml
make cantilever cantilever.toml
make sphere thick_sphere.toml
make sphere_quadratic thick_sphere.toml quadratic
if [ -n "$full" ]; then
  cases="plate:26,52,104,130,208,270 plate_quadratic:13,26,52 ring:42,104,208 cantilever:20,52,104
         sphere:50,100,200,250,400,500 sphere_quadratic:25,50,100"
else
  cases="plate:26,104 plate_quadratic:26 ring:104 cantilever:52 sphere:50,100 sphere_quadratic:50"
fi
printf "%-17s %8s %8s %8s %8s %8s %7s %7s\n" case unknowns seconds "peak MB" "est. s" "est. MB" "t ratio" "M ratio"
for entry in $cases; do
  name=${entry%%:*}
  sizes=${entry#*:}
  for n in ${sizes//,/ }; do
    /usr/bin/time -f "%e %M" -o "$work/time" "$exe" run "$work/$name.toml" -q --set n="$n" -o "$work/out" > /dev/null 2>&1
    read -r seconds kb < "$work/time"
    /usr/bin/python3 - "$work/out/summary.json" "$name" "$seconds" "$kb" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); name, seconds, kb = sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
e = s["estimate"]; mb = kb * 1024 / 1e6
print("%-17s %8d %8.2f %8.0f %8.2f %8.0f %7.2f %7.2f" % (name, s["results"]["solve"]["unknowns"], seconds, mb,
      e["seconds"], e["memory_bytes"] / 1e6, e["seconds"] / seconds, e["memory_bytes"] / 1e6 / mb))
PY
  done
done
