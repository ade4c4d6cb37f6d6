#!/usr/bin/env python3
"""Compare two output folders of `bemcontact run` number by number.

Usage: compare_runs.py REFERENCE CANDIDATE TOLERANCE [FILE ...]

Every numeric column of each CSV file is compared relative to its largest magnitude in
the reference (columns that vanish compare absolutely against 1e-300); non-numeric cells
must be equal. Exit 0 when every difference is within TOLERANCE, 1 otherwise (each
failure printed)."""
import csv
import math
import sys


def read(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare(reference, candidate, tolerance):
    a, b = read(reference), read(candidate)
    failures = []
    if len(a) != len(b) or (a and a[0] != b[0]):
        return [f"{candidate}: {len(b)} rows / header {b[0] if b else []} against {len(a)} / {a[0] if a else []}"]
    header, rows_a, rows_b = a[0], a[1:], b[1:]
    worst = 0.0
    for c, name in enumerate(header):
        column = [number(r[c]) for r in rows_a]
        scale = max((abs(v) for v in column if v is not None and math.isfinite(v)), default=0.0)
        for row, (ra, rb) in enumerate(zip(rows_a, rows_b)):
            va, vb = number(ra[c]), number(rb[c])
            if va is None or vb is None:
                if ra[c] != rb[c]:
                    failures.append(f"{candidate}: row {row + 1} column {name}: '{rb[c]}' against '{ra[c]}'")
                continue
            difference = abs(va - vb) / max(scale, 1e-300)
            worst = max(worst, difference)
            if not difference <= tolerance:
                failures.append(f"{candidate}: row {row + 1} column {name}: {vb} against {va} "
                                f"(relative to the column {difference:.3g})")
    print(f"{candidate}: {len(rows_a)} rows, largest relative difference {worst:.3g}")
    return failures


def main():
    if len(sys.argv) < 5:
        print(__doc__)
        return 2
    reference, candidate, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])
    failures = []
    for name in sys.argv[4:]:
        failures += compare(f"{reference}/{name}", f"{candidate}/{name}", tolerance)
    for f in failures[:20]:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
