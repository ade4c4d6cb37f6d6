#!/usr/bin/env python3
"""Writes a decomposition file of n x n circular fibres in a square matrix under remote
tension (plane strain): the geometry of dd/fibre_composite.hpp, as a problem file.

Usage: fibre_composite_toml.py N [ELEMENTS_PER_QUARTER] > file.toml

Fibre radius R = 1, pitch 4 R, matrix half-width W = 2 N + 4 (at least 2 R of matrix
around the outer fibres), glass (E 70 000, nu 0.22) in epoxy (E 3 500, nu 0.35),
s11 = 1 on x = +-W; the matrix held by two points on y = 0."""
import sys


def main():
    n = int(sys.argv[1])
    per_quarter = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    W = 2.0 * n + 4.0
    pitch = 4.0
    first = -0.5 * (n - 1) * pitch
    centres = [(first + (k % n) * pitch, first + (k // n) * pitch) for k in range(n * n)]
    out = [f"# {n} x {n} glass fibres in epoxy under remote tension (plane strain); written by",
           f"# scripts/fibre_composite_toml.py {n} {per_quarter}. {n * n + 1} subdomains.",
           f'title = "Fibre composite, {n * n} fibres"',
           'analysis = "plane_strain"', "", "[parameters]", "sigma = 1.0", ""]
    out += ["[[subdomain]]", 'name = "matrix"', "[subdomain.material]", "E = 3500.0", "nu = 0.35"]
    corners = [(-W, -W), (W, -W), (W, W), (-W, W)]
    sides = ["bottom", "right", "top", "left"]
    side_elements = max(8, int(2 * W))
    for s in range(4):
        a, b = corners[s], corners[(s + 1) % 4]
        out += ["[[subdomain.boundary]]", f'name = "{sides[s]}"', f"from = [{a[0]}, {a[1]}]",
                f"to = [{b[0]}, {b[1]}]", f"elements = {side_elements}"]
        if sides[s] == "right":
            out += ['t1 = "sigma"', "t2 = 0.0"]
        elif sides[s] == "left":
            out += ['t1 = "-sigma"', "t2 = 0.0"]
        else:
            out += ["t1 = 0.0", "t2 = 0.0"]
    quarters = lambda c: [(c[0] + 1, c[1]), (c[0], c[1] + 1), (c[0] - 1, c[1]), (c[0], c[1] - 1)]
    for k, c in enumerate(centres):
        q = quarters(c)
        for j in (3, 2, 1, 0):  # the hole runs clockwise
            a, b = q[(j + 1) % 4], q[j]
            out += ["[[subdomain.boundary]]", 'shape = "arc"', f"from = [{a[0]}, {a[1]}]", f"to = [{b[0]}, {b[1]}]",
                    f"center = [{c[0]}, {c[1]}]", 'direction = "cw"', f"elements = {per_quarter}",
                    f'interface = "fibre{k + 1}_q{j + 1}"']
    out += ["[[subdomain.constraint]]", f"at = [{-W}, 0.0]", "u1 = 0.0", "u2 = 0.0",
            "[[subdomain.constraint]]", f"at = [{W}, 0.0]", "u2 = 0.0", ""]
    for k, c in enumerate(centres):
        q = quarters(c)
        out += ["[[subdomain]]", f'name = "fibre{k + 1}"', "[subdomain.material]", "E = 70000.0", "nu = 0.22"]
        for j in range(4):
            a, b = q[j], q[(j + 1) % 4]
            out += ["[[subdomain.boundary]]", 'shape = "arc"', f"from = [{a[0]}, {a[1]}]", f"to = [{b[0]}, {b[1]}]",
                    f"center = [{c[0]}, {c[1]}]", 'direction = "ccw"', f"elements = {per_quarter}",
                    f'interface = "fibre{k + 1}_q{j + 1}"']
        out += ["[subdomain.interior]", f"points = [[{c[0]}, {c[1]}]]", ""]
    print("\n".join(out))


if __name__ == "__main__":
    main()
