#!/usr/bin/env python3
"""Writes a decomposition file of the thesis' plate in tension (IV.5) cut into N strips of
unit height, 2 wide, with ACROSS elements across and UP elements up each side: balanced
subdomains for measuring distributed runs (bench/mpi_scaling.sh).

Usage: strips_toml.py N ACROSS UP > file.toml"""
import sys


def main():
    n, across, up = (int(a) for a in sys.argv[1:4])
    out = [f"# {n} strips of the plate in tension (IV.5), {across} x {up} elements each; written by",
           f"# scripts/strips_toml.py {n} {across} {up}.",
           f'title = "Plate in tension in {n} strips"', 'analysis = "plane_stress"', ""]
    for s in range(n):
        y0, y1 = float(s), float(s + 1)
        out += ["[[subdomain]]", f'name = "strip{s + 1}"', "[subdomain.material]", "E = 100000.0", "nu = 0.1"]
        pieces = [("bottom", (-1.0, y0), (1.0, y0), across), ("right", (1.0, y0), (1.0, y1), up),
                  ("top", (1.0, y1), (-1.0, y1), across), ("left", (-1.0, y1), (-1.0, y0), up)]
        for name, a, b, elements in pieces:
            out += ["[[subdomain.boundary]]", f'name = "{name}"', f"from = [{a[0]}, {a[1]}]", f"to = [{b[0]}, {b[1]}]",
                    f"elements = {elements}"]
            if name == "bottom":
                out += [f'interface = "y{s}"'] if s > 0 else ["u2 = 0.0", "t1 = 0.0"]
            elif name == "top":
                out += [f'interface = "y{s + 1}"'] if s < n - 1 else ["t1 = 0.0", "t2 = 1.0"]
            else:
                out += ["t1 = 0.0", "t2 = 0.0"]
        if s == 0:
            out += ["[[subdomain.constraint]]", "at = [0.0, 0.0]", "u1 = 0.0"]
        out.append("")
    print("\n".join(out))


if __name__ == "__main__":
    main()
