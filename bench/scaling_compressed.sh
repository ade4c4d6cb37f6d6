#!/usr/bin/env bash
# Dense against compressed (hierarchical-matrix) solves of one plane body: the plate with a
# hole of examples/plate_hole.toml with every boundary's element count times n, at about
# 2k, 8k, 32k and 128k unknowns. Prints unknowns, wall time, peak memory (RSS) and the
# boundary solution's difference from the dense one where both run, then the fitted growth
# exponents. Usage: bench/scaling_compressed.sh [build dir] (default build); takes ~4 min.
set -euo pipefail
build=${1:-build}
exe=$(realpath "$build/bemcontact")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
src=$(dirname "$0")/../examples/plate_hole.toml
# n in the element counts; interior points cut to two.
sed -e 's/^W = 20.0/W = 20.0\nn = 1/' -e 's/^elements = \([0-9]*\)/elements = "n*\1"/' -e '/^\[interior\]/,$d' "$src" \
  > "$work/base.toml"
printf '\n[interior]\npoints = [[2.0, 0.5], [1.2, 1.2]]\n' >> "$work/base.toml"
for op in dense compressed; do
  { cat "$work/base.toml"; printf '[solver]\noperator = "%s"\n' "$op"; } > "$work/$op.toml"
done
compare() {  # max relative difference of u, t, stress columns between two boundary.csv
  /usr/bin/python3 - "$1" "$2" <<'PY'
import csv, sys
d = list(csv.DictReader(open(sys.argv[1]))); c = list(csv.DictReader(open(sys.argv[2])))
def rel(keys):
    e = max(max(abs(float(a[k]) - float(b[k])) for k in keys) for a, b in zip(d, c))
    return e / max(max(abs(float(a[k])) for k in keys) for a in d)
print("u %.1e  t %.1e  stress %.1e" % (rel(["u1", "u2"]), rel(["t1", "t2"]), rel(["s11", "s22", "s12"])))
PY
}
printf "%-10s %-8s %10s %10s %12s  %s\n" operator n unknowns seconds "peak MB" "against dense"
rows=()
for n in 14 56 224 896; do
  for op in dense compressed; do
    [ "$op" = dense ] && [ "$n" -gt 56 ] && continue   # 32k dense: 33 GB
    out="$work/out_${op}_$n"
    /usr/bin/time -f "%e %M" -o "$work/time" "$exe" run "$work/$op.toml" -q --set n=$n -o "$out"
    read -r seconds kb < "$work/time"
    unknowns=$(/usr/bin/python3 -c "import json;print(json.load(open('$out/summary.json'))['results']['solve']['unknowns'])")
    diff=""
    [ "$op" = compressed ] && [ -d "$work/out_dense_$n" ] && diff=$(compare "$work/out_dense_$n/boundary.csv" "$out/boundary.csv")
    printf "%-10s %-8s %10s %10s %12.0f  %s\n" "$op" "$n" "$unknowns" "$seconds" "$((kb / 1024))" "$diff"
    rows+=("$op $unknowns $seconds $kb")
  done
done
printf '%s\n' "${rows[@]}" | /usr/bin/python3 -c '
import sys, math
data = {}
for line in sys.stdin:
    op, n, s, kb = line.split(); data.setdefault(op, []).append((int(n), float(s), int(kb)))
for op, rows in data.items():
    (n0, s0, m0), (n1, s1, m1) = rows[0], rows[-1]
    print("%s: time ~ N^%.2f, memory ~ N^%.2f (from %d to %d unknowns)" % (op, math.log(s1 / s0) / math.log(n1 / n0), math.log(m1 / m0) / math.log(n1 / n0), n0, n1))'
