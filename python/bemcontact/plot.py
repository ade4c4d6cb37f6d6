"""Figures of a problem file or of a run's output folder (matplotlib, no display needed).

    python3 -m bemcontact.plot SOURCE [-o DIR] [--format png|svg]
    bemcontact plot SOURCE ...            (the same, from the command line)

SOURCE a problem file: the mesh of every body (element ends, normals, boundary names,
contact pairs), so that a wrong arc direction or a reversed contour shows before solving.
SOURCE an output folder: the mesh again (from the problem file named in summary.json when
it is unchanged), von Mises and principal stresses on each interior grid, contact pressure
and shear per contact (with the closed form when the run names one; against the angle
about the centre of curvature for a conformal contact), load-history curves with the Q -
delta loop of a tangential force load, as computed and without the bulk compliance; for a
contact that wears, its scar's evolution over the load cycles (wear_<contact>); for an
elastoplastic run, the plastic zone, the cells' von Mises stress and the load-displacement
curve with its unloading branch (plasticity), and for a ball indentation the load-depth
curve and the dent left after unloading.
"""
import argparse
import hashlib
import json
import os
import pathlib
import sys
import urllib.parse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import numpy as np  # noqa: E402

from . import Problem, Result, Table  # noqa: E402


def _vtk_names(vtk_text, field):
    """A string array of a legacy VTK file's field data (percent-decoded)."""
    lines = vtk_text.splitlines()
    for k, line in enumerate(lines):
        words = line.split()
        if len(words) == 4 and words[0] == field and words[3] == "string":
            count = int(words[2])
            return [urllib.parse.unquote(w) for w in lines[k + 1:k + 1 + count]]
    return []


def _stems(result, suffix):
    """Region stems of files named <stem><suffix> ('' for a one-body problem's file)."""
    stems = []
    for name in result.names():
        if name.endswith(suffix):
            stem = name[: -len(suffix)]
            stems.append(stem[:-1] if stem.endswith("_") else stem)
    return stems


def _file(stem, suffix):
    return f"{stem}_{suffix}" if stem else suffix


def _finish(fig, path):
    """Save the figure to `path` and close it (returns the path); with no path, return the
    figure itself (to draw on it, or to read what it shows)."""
    fig.tight_layout()
    if path is None:
        return fig
    fig.savefig(path)
    plt.close(fig)
    return path


def _size(x, y):
    return max(np.ptp(x), np.ptp(y), 1e-300)


def mesh_figure(mesh_result, title, path=None):
    """Elements (ends marked), nodes, outward normals and boundary names of every region."""
    stems = _stems(mesh_result, "mesh_elements.csv")
    fig, ax = plt.subplots(figsize=(8, 7))
    xs, ys = [], []
    for stem in stems:
        nodes = mesh_result.table(_file(stem, "mesh_nodes.csv"))
        xs.extend(nodes["x"])
        ys.extend(nodes["y"])
    size = _size(np.array(xs), np.array(ys)) if xs else 1.0
    colours = plt.get_cmap("tab10")
    for r, stem in enumerate(stems):
        elements = mesh_result.table(_file(stem, "mesh_elements.csv"))
        nodes = mesh_result.table(_file(stem, "mesh_nodes.csv"))
        names = _vtk_names(mesh_result.text(_file(stem, "mesh.vtk")), "boundary_names")
        for piece in np.unique(elements["piece"]).astype(int):
            on = elements["piece"] == piece
            colour = colours((r * 3 + piece) % 10)
            for e in np.flatnonzero(on):
                xe = [elements["x_start"][e], elements["x_end"][e]]
                ye = [elements["y_start"][e], elements["y_end"][e]]
                middle = int(elements["node_middle"][e]) if "node_middle" in elements else -1
                if middle >= 0:  # quadratic: through its middle node
                    xe.insert(1, nodes["x"][middle])
                    ye.insert(1, nodes["y"][middle])
                ax.plot(xe, ye, "-", color=colour, lw=1.2)
            # Element ends: short ticks across the element (along its normal).
            tick = 0.012 * size
            for end in ("start", "end"):
                ex, ey = elements[f"x_{end}"][on], elements[f"y_{end}"][on]
                nx, ny = elements["nx"][on], elements["ny"][on]
                ticks = np.stack([np.stack([ex - tick * nx, ey - tick * ny], 1),
                                  np.stack([ex + tick * nx, ey + tick * ny], 1)], 1)
                ax.add_collection(LineCollection(ticks, colors="k", linewidths=0.8))
            at = nodes["piece"] == piece
            ax.plot(nodes["x"][at], nodes["y"][at], "o", mfc="none", mec=colour, ms=3)
            ax.quiver(nodes["x"][at], nodes["y"][at], nodes["nx"][at], nodes["ny"][at], color=colour,
                      angles="xy", scale_units="xy", scale=1.0 / (0.04 * size), width=0.002)
            mid = np.flatnonzero(at)[len(np.flatnonzero(at)) // 2] if at.any() else None
            if mid is not None:
                label = names[piece] if piece < len(names) else f"piece {piece}"
                if stem:
                    label = f"{stem}: {label}"
                ax.annotate(label, (nodes["x"][mid], nodes["y"][mid]),
                            xytext=(nodes["x"][mid] + 0.06 * size * nodes["nx"][mid],
                                    nodes["y"][mid] + 0.06 * size * nodes["ny"][mid]),
                            fontsize=8, color=colour, ha="center",
                            arrowprops={"arrowstyle": "-", "color": colour, "lw": 0.5})
    for name in mesh_result.names():
        if name.endswith("_pairs.csv"):
            pairs = mesh_result.table(name)
            for k in range(len(pairs)):
                ax.plot([pairs["x1"][k], pairs["x2"][k]], [pairs["y1"][k], pairs["y2"][k]], "-", color="0.5", lw=0.5)
    ax.set_aspect("equal")
    ax.margins(0.1)  # room for the names written outside the boundary
    ax.set_title(f"{title}\nelements (| ends), nodes (o), outward normals, boundary names", fontsize=9)
    ax.set_xlabel("x (r)")
    ax.set_ylabel("y (z)")
    return _finish(fig, path)


def principal_stresses(s11, s22, s12):
    """In-plane principal stresses (s1 >= s2) from the components (closed form)."""
    centre = 0.5 * (s11 + s22)
    radius = np.hypot(0.5 * (s11 - s22), s12)
    return centre + radius, centre - radius


def grid_triangles(table):
    """Two triangles per grid square whose four corners are in the table (interior.csv)."""
    at = {}
    for k, (i, j) in enumerate(zip(table["grid_column"].astype(int), table["grid_row"].astype(int))):
        if i >= 0:
            at[(i, j)] = k
    triangles = []
    for (i, j), a in at.items():
        b, c, d = at.get((i + 1, j)), at.get((i + 1, j + 1)), at.get((i, j + 1))
        if None not in (b, c, d):
            triangles += [[a, b, c], [a, c, d]]
    return np.array(triangles, dtype=int).reshape(-1, 3)


def _outline(ax, boundary):
    for name in dict.fromkeys(boundary["boundary"]):
        on = boundary["boundary"] == name
        ax.plot(boundary["x"][on], boundary["y"][on], "-", color="k", lw=0.8)


def interior_figure(result, stem, title, path=None):
    table = result.table(_file(stem, "interior.csv"))
    boundary = result.table(_file(stem, "boundary.csv"))
    s1, s2 = principal_stresses(table["s11"], table["s22"], table["s12"])
    triangles = grid_triangles(table)
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    for ax, values, name in zip(axes, (table["von_mises"], s1, s2),
                                ("von Mises", "max principal s1", "min principal s2")):
        if len(triangles):
            mesh = mtri.Triangulation(table["x"], table["y"], triangles)
            shown = ax.tricontourf(mesh, values, levels=20, cmap="viridis")
        else:
            shown = ax.scatter(table["x"], table["y"], c=values, s=12, cmap="viridis")
        fig.colorbar(shown, ax=ax, shrink=0.8)
        _outline(ax, boundary)
        # The grid's region, with the boundary around it.
        margin = 0.05 * _size(table["x"], table["y"])
        ax.set_xlim(table["x"].min() - margin, table["x"].max() + margin)
        ax.set_ylim(table["y"].min() - margin, table["y"].max() + margin)
        ax.set_aspect("equal")
        ax.set_title(name, fontsize=9)
    fig.suptitle(f"{title}: {stem or 'body'} (interior points; stresses in the file's units)", fontsize=10)
    return _finish(fig, path)


def contact_angles(pairs):
    """The pairs' angle about the contact's centre of curvature, for a conformal contact.

    When side 1's pairs lie on a circle (fitted in least squares; rms distance under 1e-4
    of its radius, spanning over 1 degree) and the contact is conformal there, that is the
    other body sits in side 1's hollow (its centre lies on the side the pair normals point
    to: a pin in a hole) or the pairs wrap over 60 degrees about it (a shrink fit):
    returns (angles in degrees, counter-clockwise from the middle of the zone, the mean
    direction of its pairs from the centre; from +x when they wrap all round; centre,
    radius). Otherwise None: the pressure is drawn against the coordinate.
    """
    x, y = np.asarray(pairs["x"], float), np.asarray(pairs["y"], float)
    if len(x) < 3:
        return None
    x0, y0 = x.mean(), y.mean()
    u, v = x - x0, y - y0
    # x^2 + y^2 + D x + E y + F = 0 (Kasa), about the pairs' mean for conditioning.
    (D, E, F), *_ = np.linalg.lstsq(np.stack([u, v, np.ones_like(u)], 1), -(u ** 2 + v ** 2), rcond=None)
    centre = np.array([x0 - D / 2, y0 - E / 2])
    radius_squared = D ** 2 / 4 + E ** 2 / 4 - F
    if not np.isfinite(radius_squared) or radius_squared <= 0:
        return None
    radius = np.sqrt(radius_squared)
    arm = np.stack([x - centre[0], y - centre[1]], 1)
    distance = np.hypot(arm[:, 0], arm[:, 1])
    if np.sqrt(np.mean((distance - radius) ** 2)) > 1e-4 * radius:
        return None
    direction = arm / distance[:, None]
    middle = direction.mean(axis=0)
    reference = middle / np.hypot(*middle) if np.hypot(*middle) > 0.1 else np.array([1.0, 0.0])
    angles = np.degrees(np.arctan2(reference[0] * direction[:, 1] - reference[1] * direction[:, 0],
                                   direction @ reference))
    span = np.ptp(angles) if np.hypot(*middle) > 0.1 else 360.0
    hollow = np.mean(-(arm[:, 0] * pairs["nx"] + arm[:, 1] * pairs["ny"])) > 0.0  # normals toward the centre
    if span < 1.0 or not (hollow or span > 60.0):
        return None
    return angles, centre, radius


def contact_figure(result, name, reference, friction, title, path=None):
    """Pressure and shear along the contact at the end of the history: against the
    coordinate (x or r), or, for a conformal contact, the angle about its centre of
    curvature (contact_angles)."""
    pairs = result.contact(name)
    conformal = contact_angles(pairs)
    r = pairs["coordinate"] if conformal is None else conformal[0]
    order = np.argsort(r)
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(r[order], -pairs["p_n"][order], "o-", ms=3, label="pressure -p_n")
    ax.plot(r[order], pairs["p_t"][order], "s-", ms=3, label="shear p_t")
    if reference and reference.get("name") == "hertz_sphere" and conformal is None:
        a, p0 = reference["a"], reference["p0"]
        rr = np.linspace(0.0, a, 200) * np.sign(np.median(r) or 1.0)
        ax.plot(rr, p0 * np.sqrt(np.clip(1 - (rr / a) ** 2, 0, None)), "k--", label=f"Hertz (a = {a:.4g})")
    for status, colour in (("stick", "tab:green"), ("slip", "tab:red")):
        on = pairs["status"] == status
        if on.any() and friction > 0:
            ax.plot(r[on], np.zeros(on.sum()), "|", color=colour, ms=10, label=status)
    ax.axhline(0.0, color="0.6", lw=0.5)
    if conformal is None:
        ax.set_xlabel("position along the contact (coordinate: x or r; y or z on a side face)")
    else:
        _, centre, radius = conformal
        centre = np.where(np.abs(centre) < 1e-9 * radius, 0.0, centre)  # round-off of the fit
        ax.set_xlabel(f"angle about the centre of curvature ({centre[0]:.4g}, {centre[1]:.4g}) (radius {radius:.4g}), "
                      "degrees counter-clockwise from the middle of the zone", fontsize=8)
    ax.set_ylabel("traction")
    ax.set_title(f"{title}: contact '{name}' at the end of the history", fontsize=9)
    ax.legend(fontsize=8)
    return _finish(fig, path)


def tangential_loads(result, names):
    """The force loads that a contact's tangential force carries: a motions.csv force
    column equal to +-tangential_force of the contact's steps (within 1 % of its largest
    value, which is not 0). Per load: a dict with the column stem (`load`), `contact`,
    `time`, the force `Q` and the displacement `delta` (<stem>_force, <stem>_displacement)."""
    if "motions.csv" not in result.names():
        return []
    motions = result.motions()
    found = []
    for column in motions.columns[2:]:
        stem = column[: -len("_force")]
        if not column.endswith("_force") or f"{stem}_displacement" not in motions:
            continue
        Q = motions[column]
        largest = np.abs(Q).max()
        if largest == 0.0:
            continue
        for name in names:
            T = result.contact_steps(name)["tangential_force"]
            if len(T) == len(Q) and min(np.abs(Q - T).max(), np.abs(Q + T).max()) <= 0.01 * largest:
                found.append({"load": stem, "contact": name, "time": motions["time"], "Q": Q,
                              "delta": motions[f"{stem}_displacement"]})
                break
    return found


def without_compliance(Q, delta):
    """The Q - delta loop without the bulk compliance: the elastic part that the stick
    state carries, subtracted as the slope k0 of the loading branch's first step (from the
    last step at which Q is 0 to the next; from the origin when Q is not 0 at the first).
    Returns (first, slip, k0): from index `first` (that step) on, slip = delta - delta0 -
    (Q - Q0) / k0, which starts at 0 and keeps the loop's area (the energy dissipated by a
    cycle: the subtracted part is a function of Q alone). None when Q never leaves 0."""
    Q, delta = np.asarray(Q, float), np.asarray(delta, float)
    moving = np.flatnonzero(Q != 0.0)
    if len(moving) == 0:
        return None
    onset = moving[0]
    Q0, delta0 = (Q[onset - 1], delta[onset - 1]) if onset > 0 else (0.0, 0.0)
    if delta[onset] == delta0:
        return None
    k0 = (Q[onset] - Q0) / (delta[onset] - delta0)
    first = max(onset - 1, 0)
    return first, delta[first:] - delta0 - (Q[first:] - Q0) / k0, k0


def history_figure(result, names, title, path=None):
    """Against time: normal force, contact and stick sizes, dissipated energy, motions and
    forces; with a tangential force load (fretting), its Q - delta loop as computed and
    with the bulk compliance removed (without_compliance)."""
    loops = tangential_loads(result, names)
    fig, grid = plt.subplots(2, 3 if loops else 2, figsize=(16 if loops else 11, 7), squeeze=False)
    axes = grid[:, :2]
    for name in names:
        steps = result.contact_steps(name)
        t = steps["time"]
        axes[0, 0].plot(t, steps["normal_force"], ".-", label=name)
        axes[0, 1].plot(t, steps["a"], ".-", label=f"{name}: a")
        # Frictionless (or never sticking): no stick size and nothing dissipated to draw.
        if np.any(steps["c"] != 0.0):
            axes[0, 1].plot(t, steps["c"], ".--", label=f"{name}: c (stick)")
        # Already cumulative: the energy dissipated since the start (docs/contact.md).
        if np.any(np.abs(steps["dissipated_energy"]) > 0.0):
            axes[1, 0].plot(t, steps["dissipated_energy"], ".-", label=name)
    motions_drawn = False
    if "motions.csv" in result.names():
        motions = result.motions()
        motions_drawn = len(motions.columns) > 2
        # Forces on the left axis, displacements (much smaller numbers) on the right.
        right = axes[1, 1].twinx()
        for k, column in enumerate(motions.columns[2:]):
            ax = axes[1, 1] if column.endswith(("_force", "_moment")) else right
            ax.plot(motions["time"], motions[column], ".-" if ax is right else "o-", ms=3, label=column,
                    color=plt.get_cmap("tab10")(k % 10))
        axes[1, 1].set_ylabel("forces (moments)")
        right.set_ylabel("displacements (rotations)")
        if right.has_data():
            right.legend(fontsize=7, loc="lower right")
    for ax, label in zip(axes.flat, ("normal force", "contact and stick sizes", "dissipated energy since the start",
                                     "prescribed / computed motions and forces")):
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("time")
    # Said rather than left blank.
    for ax, drawn, empty in ((axes[1, 0], axes[1, 0].has_data(), "nothing dissipated (frictionless)"),
                             (axes[1, 1], motions_drawn, "no force loads or moving rigid bodies")):
        if not drawn:
            ax.text(0.5, 0.5, empty, ha="center", va="center", transform=ax.transAxes, fontsize=9, color="0.4")
    if loops:
        raw, slip = grid[0, 2], grid[1, 2]
        for loop in loops:
            raw.plot(loop["delta"], loop["Q"], ".-", ms=3, label=f"{loop['load']} ({loop['contact']})")
            removed = without_compliance(loop["Q"], loop["delta"])
            if removed is not None:
                first, delta_slip, k0 = removed
                slip.plot(delta_slip, loop["Q"][first:], ".-", ms=3, label=f"{loop['load']}: k0 = {k0:.4g}")
        raw.set_title("Q - delta loop (as computed)", fontsize=9)
        raw.set_xlabel("delta")
        slip.set_title("Q - delta loop, bulk compliance removed (k0: first step's slope)", fontsize=9)
        slip.set_xlabel("delta - delta0 - (Q - Q0) / k0")
        for ax in (raw, slip):
            ax.set_ylabel("Q")
            ax.axhline(0.0, color="0.6", lw=0.5)
            ax.axvline(0.0, color="0.6", lw=0.5)
    for ax in grid.flat:
        if ax.has_data():
            ax.legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    return _finish(fig, path)


def wear_cycles(cycles, count=6):
    """Indices of about `count` cycles spread logarithmically from the first to the last
    (both kept): the computed cycle nearest each of geomspace(first, last, count)."""
    logs = np.log(np.maximum(cycles, 1.0))
    targets = np.linspace(logs[0], logs[-1], count)
    return np.unique([np.argmin(np.abs(logs - t)) for t in targets])


def wear_figure(result, name, title, path=None):
    """The wear scar of contact `name` over the load cycles (<name>_wear.csv and
    <name>_wear_profile.csv): worn depth and pressure -p_n against the coordinate at about
    six cycles spread logarithmically (wear_cycles; side 1 solid, side 2 dashed when it
    wears), worn volume per side, and peak and centre pressure (stick half-width c on a
    twin axis when there is a stick zone) against the cycle."""
    history = result.table(_file(name, "wear.csv"))
    profile = result.table(_file(name, "wear_profile.csv"))
    cycles = history["cycle"]
    side2 = bool(np.any(profile["depth2"] != 0.0))
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    (depth, pressure), (volume, peak) = axes
    picked = wear_cycles(cycles)
    colours = plt.get_cmap("viridis")
    for k, index in enumerate(picked):
        colour = colours(k / max(len(picked) - 1, 1))
        rows = profile["cycle"] == cycles[index]
        order = np.argsort(profile["coordinate"][rows])
        x = profile["coordinate"][rows][order]
        label = f"N = {cycles[index]:.0f}"
        depth.plot(x, profile["depth1"][rows][order], "-", color=colour, label=label)
        if side2:
            depth.plot(x, profile["depth2"][rows][order], "--", color=colour)
        pressure.plot(x, -profile["p_n"][rows][order], ".-", ms=3, color=colour, label=label)
    volume.plot(cycles, history["worn_volume1"], ".-", ms=3, label="side 1")
    if side2 or np.any(history["worn_volume2"] != 0.0):
        volume.plot(cycles, history["worn_volume2"], ".--", ms=3, label="side 2")
    peak.plot(cycles, history["peak_pressure"], ".-", ms=3, label="peak pressure")
    peak.plot(cycles, history["centre_pressure"], ".-", ms=3, label="centre pressure")
    if np.any(history["c"] > 0.0):
        stick = peak.twinx()
        stick.plot(cycles, history["c"], ".:", ms=3, color="tab:green", label="c (stick)")
        stick.set_ylabel("stick half-width c")
        stick.legend(fontsize=7, loc="lower right")
    for ax in (depth, pressure):
        ax.set_xlabel("position along the contact (coordinate)")
    for ax in (volume, peak):
        ax.set_xlabel("load cycles N")
        if cycles[0] > 0 and cycles[-1] > 10 * cycles[0]:
            ax.set_xscale("log")
    for ax, label in zip(axes.flat, ("worn depth (side 1 solid" + (", side 2 dashed)" if side2 else ")"),
                                     "contact pressure -p_n at the cycle's end",
                                     "worn area per unit thickness", "pressure at the cycle's end")):
        ax.set_title(label, fontsize=9)
        ax.legend(fontsize=7)
    fig.suptitle(f"{title}: wear of contact '{name}' ({len(cycles)} computed cycles)", fontsize=10)
    return _finish(fig, path)


def vtk_polygons(vtk_text):
    """The polygons of a legacy VTK POLYDATA file (cells.vtk): a list of (k, 2) arrays."""
    words = vtk_text.split()
    at = words.index("POINTS")
    count = int(words[at + 1])
    points = np.array(words[at + 3:at + 3 + 3 * count], float).reshape(count, 3)[:, :2]
    at = words.index("POLYGONS")
    polygons, k = [], at + 3
    for _ in range(int(words[at + 1])):
        n = int(words[k])
        polygons.append(points[np.array(words[k + 1:k + 1 + n], int)])
        k += 1 + n
    return polygons


def loaded_boundary(steps, names):
    """The boundary whose force does the most work over the steps (the largest range of
    f . u: a roller's reaction, normal to its motion, does none), and the unit direction of
    its largest force: the load-displacement curve is that force and the mean displacement
    along it. None when no boundary works."""
    best, most = None, 0.0
    for name in names:
        f = np.stack([steps[f"{name}_f1"], steps[f"{name}_f2"]], axis=1)
        u = np.stack([steps[f"{name}_u1"], steps[f"{name}_u2"]], axis=1)
        work = np.ptp(np.concatenate([[0.0], np.sum(f * u, axis=1)]))
        if work > most:
            peak = f[np.argmax(np.linalg.norm(f, axis=1))]
            best, most = (name, peak / np.linalg.norm(peak)), work
    return best


def plasticity_figure(result, stem, title, path=None):
    """An elastoplastic run (<stem>cells.csv, steps.csv; docs/plasticity.md): the cells
    coloured by the equivalent plastic strain and by the von Mises stress at the end of the
    history (after unloading: the residual stresses), and the force against the
    mean displacement of the boundary whose force works most (loaded_boundary), with its
    unloading branch."""
    cells = result.table(_file(stem, "cells.csv"))
    # A body alone writes <stem>steps.csv; one in contact <stem>plastic_steps.csv, and a
    # ball indentation its load-depth curve (indentation.csv) and its dent.
    names = result.names()
    steps = result.table(_file(stem, "steps.csv") if _file(stem, "steps.csv") in names else
                         _file(stem, "plastic_steps.csv"))
    indentation = "indentation.csv" in names
    fig, axes = plt.subplots(1, 4 if indentation else 3, figsize=(21 if indentation else 16, 5))
    vtk = _file(stem, "cells.vtk")
    polygons = vtk_polygons(result.text(vtk)) if vtk in result.names() else None
    for ax, column, label, cmap in ((axes[0], "equivalent_plastic_strain", "equivalent plastic strain", "magma_r"),
                                    (axes[1], "von_mises", "von Mises stress", "viridis")):
        values = cells[column]
        if polygons is not None:
            from matplotlib.collections import PolyCollection
            collection = PolyCollection(polygons, array=values, cmap=cmap, edgecolors="0.7", linewidths=0.2)
            ax.add_collection(collection)
            ax.autoscale_view()
            fig.colorbar(collection, ax=ax, shrink=0.8)
        else:
            drawn = ax.scatter(cells["x"], cells["y"], c=values, cmap=cmap, s=8)
            fig.colorbar(drawn, ax=ax, shrink=0.8)
        if column == "equivalent_plastic_strain" and np.any(values > 0.0):
            yielded = values > 0.0
            ax.plot(cells["x"][yielded], cells["y"][yielded], ".", color="k", ms=1.5)
        ax.set_aspect("equal")
        ax.set_title(f"{label} of the cells at the end ({int(np.sum(cells['equivalent_plastic_strain'] > 0))} "
                     "yielded: dots)" if column == "equivalent_plastic_strain" else f"{label} of the cells at the end",
                     fontsize=9)
    boundaries = [c[:-3] for c in steps.columns if c.endswith("_u1")]
    loaded = None if indentation else loaded_boundary(steps, boundaries)
    curve = axes[2]
    if indentation:
        table = result.table("indentation.csv")
        curve.plot(np.concatenate([[0.0], table["depth"]]), np.concatenate([[0.0], table["load"]]), ".-", ms=4)
        curve.set_xlabel("depth of the ball")
        curve.set_ylabel("load")
        dent = axes[3]
        # The indented face: the highest surface facing up among the bodies' boundaries (a
        # coating's top over an elastoplastic substrate, not the substrate's bond).
        faces = []
        for name in names:
            if name.endswith("boundary.csv") and "/" not in name:
                table = result.table(name)
                up = table["ny"] > 0.5
                if np.any(up):
                    faces.append((np.max(table["y"][up]), name))
        boundary = result.table(max(faces)[1]) if faces else result.table(_file(stem, "boundary.csv"))
        top = boundary["ny"] > 0.5  # the surfaces facing up: the indented face
        order = np.argsort(boundary["x"][top])
        dent.plot(boundary["x"][top][order], (boundary["y"] + boundary["u2"])[top][order], ".-", ms=3)
        rim = boundary["x"][top][order][np.argmax((boundary["y"] + boundary["u2"])[top][order])]
        dent.set_xlim(0.0, max(3.0 * rim, 1e-300))  # the dent and its rim
        dent.set_xlabel("r")
        dent.set_ylabel("z + u_z")
        dent.set_title("the surface after the last step (the dent)", fontsize=9)
    elif loaded is not None:
        name, direction = loaded
        f = np.concatenate([[0.0], steps[f"{name}_f1"] * direction[0] + steps[f"{name}_f2"] * direction[1]])
        u = np.concatenate([[0.0], steps[f"{name}_u1"] * direction[0] + steps[f"{name}_u2"] * direction[1]])
        curve.plot(u, f, ".-", ms=4)
        curve.set_xlabel(f"mean displacement of boundary '{name}' along ({direction[0]:.3g}, {direction[1]:.3g})")
        curve.set_ylabel(f"its force along that direction")
    curve.set_title("load against displacement (loading and unloading)", fontsize=9)
    curve.axhline(0.0, color="0.6", lw=0.5)
    fig.suptitle(title, fontsize=10)
    return _finish(fig, path)


def _load_folder(folder):
    if not (folder / "summary.json").is_file():
        raise SystemExit(f"bemcontact plot: {folder} is not an output folder of bemcontact (no summary.json)")
    summary = json.loads((folder / "summary.json").read_bytes())
    # The files the run lists, recorded steps (steps/...) included.
    order = summary.get("outputs", []) + ["summary.json"]
    files = {n: (folder / n).read_bytes() for n in order if (folder / n).is_file()}
    return Result({"files": files, "report": "", "warnings": summary.get("warnings", []), "solver_failure": ""})


def figures(source, out_dir=None, fmt="png"):
    """Write the figures of `source` (problem file or output folder); returns their paths."""
    source = pathlib.Path(source)
    written = []
    if source.is_dir():
        result = _load_folder(source)
        summary = result.summary
        title = summary.get("title", "")
        out = pathlib.Path(out_dir) if out_dir else source / "figures"
        out.mkdir(parents=True, exist_ok=True)
        problem_file = pathlib.Path(summary.get("input", {}).get("path") or summary.get("input", {}).get("file", ""))
        if problem_file.is_file():
            problem = Problem.load(problem_file)
            if hashlib.sha256(problem.text.encode()).hexdigest() == summary["input"]["sha256"]:
                overrides = {k: v for k, v in summary.get("parameters", {}).items()
                             if isinstance(v, (int, float)) and k in problem.parameters and
                             isinstance(problem.parameters[k], (int, float)) and problem.parameters[k] != v}
                written.append(mesh_figure(problem.mesh(**overrides), title, out / f"mesh.{fmt}"))
            else:
                print(f"bemcontact plot: {problem_file} changed since the run; no mesh figure", file=sys.stderr)
        else:
            print(f"bemcontact plot: the problem file '{problem_file}' is not found from here; no mesh figure",
                  file=sys.stderr)
        for stem in _stems(result, "interior.csv"):
            written.append(interior_figure(result, stem, title, out / f"{_file(stem, 'interior')}.{fmt}"))
        for stem in _stems(result, "cells.csv"):
            written.append(plasticity_figure(result, stem, title, out / f"{_file(stem, 'plasticity')}.{fmt}"))
        contacts = result.contact_names()
        reference = summary.get("results", {}).get("contact", {}).get("reference")
        law = summary.get("options", {}).get("law", {})
        # Each contact's friction (options.law.contacts), or the one law of all of them.
        frictions = {c["name"]: c["friction"] for c in law.get("contacts", [])}
        for k, name in enumerate(contacts):
            friction = frictions.get(name, law.get("friction") or 0.0)
            written.append(contact_figure(result, name, reference if k == 0 else None, friction, title,
                                          out / f"contact_{name}.{fmt}"))
        for name in contacts:
            if _file(name, "wear.csv") in result.names():
                written.append(wear_figure(result, name, title, out / f"wear_{name}.{fmt}"))
        if contacts and len(result.contact_steps(contacts[0])) > 1:
            written.append(history_figure(result, contacts, title, out / f"history.{fmt}"))
    elif source.is_file():
        problem = Problem.load(source)
        out = pathlib.Path(out_dir) if out_dir else pathlib.Path(f"{source.stem}_figures")
        out.mkdir(parents=True, exist_ok=True)
        mesh = problem.mesh()
        written.append(mesh_figure(mesh, mesh.summary.get("title", source.stem), out / f"mesh.{fmt}"))
    else:
        raise SystemExit(f"bemcontact plot: no such file or folder: {source}")
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(prog="bemcontact plot", description=__doc__.split("\n\n")[0])
    parser.add_argument("source", help="problem file (.toml) or output folder of a run")
    parser.add_argument("-o", "--output", help="folder of the figures (default: SOURCE/figures or STEM_figures)")
    parser.add_argument("--format", choices=("png", "svg"), default="png")
    args = parser.parse_args(argv)
    from . import Error
    try:
        paths = figures(args.source, args.output, args.format)
    except Error as error:
        print(f"bemcontact plot: error: {error}", file=sys.stderr)
        return 2
    for path in paths:
        print(f"  wrote {os.fspath(path)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
