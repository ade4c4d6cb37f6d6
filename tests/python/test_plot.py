"""Figures: the numbers they draw, the files they write, the errors they report."""
import json
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import bemcontact as bc
from bemcontact import plot, report

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def test_principal_stresses_match_mohrs_circle():
    s1, s2 = plot.principal_stresses(np.array([3.0, 0.0, 1.0]), np.array([0.0, 0.0, 1.0]), np.array([0.0, 2.0, 0.0]))
    np.testing.assert_allclose(s1, [3.0, 2.0, 1.0])  # uniaxial, pure shear (+-tau), hydrostatic
    np.testing.assert_allclose(s2, [0.0, -2.0, 1.0])


def test_grid_triangles_are_the_vtk_cells_split_in_two(examples):
    result = bc.run(examples / "plate_hole.toml")
    triangles = plot.grid_triangles(result.interior())
    quads = result.text("interior.vtk").split("POLYGONS ")[1].split()[0]
    assert len(triangles) == 2 * int(quads)


def test_mesh_figure_of_a_problem_file_names_every_boundary(examples, binary, tmp_path):
    out = tmp_path / "figures"
    command = subprocess.run([binary, "plot", str(examples / "contact_roller_plates.toml"), "-o", str(out)],
                             capture_output=True, text=True)
    assert command.returncode == 0, command.stderr
    assert (out / "mesh.png").read_bytes()[:8] == PNG_SIGNATURE
    mesh = bc.Problem.load(examples / "contact_roller_plates.toml").mesh()
    names = plot._vtk_names(mesh.text("roller_mesh.vtk"), "boundary_names")
    data = bc.Problem.load(examples / "contact_roller_plates.toml").data()
    roller = next(b for b in data["body"] if b["name"] == "roller")
    assert names == [b["name"] for b in roller["boundary"]]


def test_figures_of_an_output_folder(examples, binary, tmp_path):
    run_dir = tmp_path / "run"
    bc.run(examples / "fretting_cylinder.toml", output=run_dir)
    command = subprocess.run([binary, "plot", str(run_dir), "--format", "svg"], capture_output=True, text=True)
    assert command.returncode == 0, command.stderr
    written = sorted(p.name for p in (run_dir / "figures").iterdir())
    assert written == ["contact_contact.svg", "history.svg", "mesh.svg"]
    for name in written:
        assert ET.parse(run_dir / "figures" / name).getroot().tag.endswith("svg")


def _csv_column(path, column):
    """One column of a CSV file, read with the csv module (not with the package's Table)."""
    import csv
    with open(path, newline="") as f:
        return np.array([float(row[column]) for row in csv.DictReader(f)])


def _axes_titled(fig, start):
    found = [ax for ax in fig.axes if ax.get_title().startswith(start)]
    assert len(found) == 1, [ax.get_title() for ax in fig.axes]
    return found[0]


@pytest.fixture(scope="module")
def fretting_run(examples, tmp_path_factory):
    """examples/fretting_cylinder.toml solved once: P, then a full cycle of Q."""
    out = tmp_path_factory.mktemp("fretting") / "run"
    bc.run(examples / "fretting_cylinder.toml", output=out)
    return out


def test_history_draws_the_dissipated_energy_as_written(fretting_run):
    # contact_steps.csv's energy is already cumulative (since the start): the curve is the
    # column itself, not its running sum (which drew it 17 times too large here).
    result = plot._load_folder(fretting_run)
    fig = plot.history_figure(result, result.contact_names(), "fretting")
    (line,) = _axes_titled(fig, "dissipated energy").get_lines()
    column = _csv_column(fretting_run / "contact_steps.csv", "dissipated_energy")
    np.testing.assert_array_equal(line.get_xdata(), _csv_column(fretting_run / "contact_steps.csv", "time"))
    np.testing.assert_array_equal(line.get_ydata(), column)
    summary = json.loads((fretting_run / "summary.json").read_text())
    assert line.get_ydata()[-1] == summary["results"]["contact"]["dissipated_energy"] > 0.0


def _loop_area(delta, Q):
    """The integral of Q d(delta) along the path (trapezoids)."""
    return float(np.sum(0.5 * (Q[1:] + Q[:-1]) * np.diff(delta)))


def test_history_has_the_fretting_loop_with_and_without_the_bulk_compliance(fretting_run):
    # The Q - delta loop of motions.csv, as computed and less its initial elastic slope. Its
    # area over the cycle Q* -> -Q* -> Q* (t = 2 to 4) is the work of Q, which friction
    # dissipates (the state at t = 4 is that at t = 2): contact_steps.csv's energy, summed
    # from the pairs' slips, gives it independently.
    result = plot._load_folder(fretting_run)
    fig = plot.history_figure(result, result.contact_names(), "fretting")
    Q = _csv_column(fretting_run / "motions.csv", "cylinder_Q_force")
    delta = _csv_column(fretting_run / "motions.csv", "cylinder_Q_displacement")
    time = _csv_column(fretting_run / "motions.csv", "time")
    (raw,) = _axes_titled(fig, "Q - delta loop (").get_lines()[:1]
    np.testing.assert_array_equal(raw.get_xdata(), delta)
    np.testing.assert_array_equal(raw.get_ydata(), Q)
    # Without the compliance: from the last step at which Q is 0, delta - delta0 - (Q - Q0) / k0
    # with k0 the slope of the next step.
    first = np.flatnonzero(Q != 0.0)[0] - 1
    assert Q[first] == 0.0 and time[first] == pytest.approx(1.0)  # P alone until t = 1
    k0 = (Q[first + 1] - Q[first]) / (delta[first + 1] - delta[first])
    slip = delta[first:] - delta[first] - (Q[first:] - Q[first]) / k0
    (removed,) = _axes_titled(fig, "Q - delta loop, bulk compliance removed").get_lines()[:1]
    np.testing.assert_allclose(removed.get_xdata(), slip, rtol=1e-12, atol=1e-12 * np.abs(delta).max())
    np.testing.assert_array_equal(removed.get_ydata(), Q[first:])
    # The compliance is most of delta: the slip part is under a tenth of it.
    assert np.abs(slip).max() < 0.1 * np.abs(delta).max()
    energy = _csv_column(fretting_run / "contact_steps.csv", "dissipated_energy")
    cycle = time >= 2.0 - 1e-12
    dissipated = energy[-1] - energy[cycle][0]
    assert _loop_area(delta[cycle], Q[cycle]) == pytest.approx(dissipated, rel=0.02)
    start = len(Q) - cycle.sum() - first
    assert _loop_area(slip[start:], Q[cycle]) == pytest.approx(dissipated, rel=0.02)


def test_conformal_contact_pressure_is_drawn_against_the_angle(examples, binary, tmp_path):
    # The pin in a hole: pairs on the hole (centre (0, 0), radius Rh = 1.01), drawn against
    # the angle about its centre from the bottom of the hole. At P = 0.34 the contact is
    # Hertz's with the relative radius Rh Rp / (Rh - Rp) = 101 and E* = E (plane stress,
    # rigid pin): a = sqrt(4 P R / (pi E)).
    run_dir = tmp_path / "pin"
    result = bc.run(examples / "contact_pin_in_hole.toml", output=run_dir)
    pairs = result.contact()
    fig = plot.contact_figure(result, "contact", None, 0.0, "pin")
    pressure = fig.axes[0].get_lines()[0]
    angles = np.degrees(np.arctan2(pairs["x"], -pairs["y"]))  # counter-clockwise from (0, -1)
    order = np.argsort(angles)
    np.testing.assert_allclose(pressure.get_xdata(), angles[order], atol=1e-9)
    np.testing.assert_array_equal(pressure.get_ydata(), -pairs["p_n"][order])
    assert "angle about the centre of curvature (0, 0) (radius 1.01)" in fig.axes[0].get_xlabel()
    p = result.summary["parameters"]
    a = np.sqrt(4 * p["P"] * (p["Rh"] * p["Rp"] / (p["Rh"] - p["Rp"])) / (np.pi * p["E"]))
    edge = np.abs(angles[pairs["p_n"] < 0.0]).max()
    element = np.degrees(2 * p["th"] / p["n"])
    assert abs(edge - np.degrees(a / p["Rh"])) < element
    # A contact that is not conformal keeps its coordinate: the fretting cylinder on a block.
    fretting = bc.run(examples / "fretting_cylinder.toml", n=20)
    assert plot.contact_angles(fretting.contact()) is None
    straight = plot.contact_figure(fretting, "contact", None, 0.3, "fretting").axes[0].get_lines()[0]
    np.testing.assert_array_equal(straight.get_xdata(), np.sort(fretting.contact()["coordinate"]))
    # The command draws both figures of the run.
    command = subprocess.run([binary, "plot", str(run_dir)], capture_output=True, text=True)
    assert command.returncode == 0, command.stderr
    assert (run_dir / "figures" / "contact_contact.png").read_bytes()[:8] == PNG_SIGNATURE


def test_plot_errors_are_clear(binary, tmp_path):
    missing = subprocess.run([binary, "plot", str(tmp_path / "nothing")], capture_output=True, text=True)
    assert missing.returncode != 0 and "no such file or folder" in missing.stderr
    (tmp_path / "empty").mkdir()
    empty = subprocess.run([binary, "plot", str(tmp_path / "empty")], capture_output=True, text=True)
    assert empty.returncode != 0 and "not an output folder" in empty.stderr
    bad = tmp_path / "bad.toml"
    bad.write_text("title = 'x'\n[material]\nE = -1\n")
    broken = subprocess.run([binary, "plot", str(bad)], capture_output=True, text=True)
    assert broken.returncode == 2 and str(bad) in broken.stderr


def test_validate_report_has_a_figure_and_a_row_per_record(binary, tmp_path):
    out = tmp_path / "report"
    command = subprocess.run([binary, "validate", "plate-hole", "cattaneo-mindlin", "--report", str(out), "-q"],
                             capture_output=True, text=True)
    assert command.returncode == 0, command.stdout + command.stderr
    records = json.loads((out / "validate.json").read_text())
    page = (out / "index.html").read_text()
    assert page.count("<img ") == 2
    assert page.count("<tr class=") == len(records)
    for case in ("plate-hole", "cattaneo-mindlin"):
        assert (out / f"{case}.png").read_bytes()[:8] == PNG_SIGNATURE


def test_report_marks_failures(tmp_path):
    records = [{"case": "c", "params": {"elements": "8"}, "quantity": "q", "computed": 1.1, "reference": 1.0,
                "error": 0.1, "comparison": "relative", "tolerance": 0.01, "passed": False},
               {"case": "c", "params": {"elements": "16"}, "quantity": "q", "computed": 1.001, "reference": 1.0,
                "error": 0.001, "comparison": "relative", "tolerance": 0.01, "passed": True}]
    page = report.write_report(records, tmp_path).read_text()
    assert "1 passed, 1 failed" in page
    assert page.count("class='no'") == 1


def test_example_scripts_run(examples, tmp_path):
    import os
    import sys
    env = dict(os.environ)
    sweep = subprocess.run([sys.executable, str(examples / "python" / "hertz_sweep.py")], capture_output=True,
                           text=True, env=env)
    assert sweep.returncode == 0, sweep.stderr
    rows = [line.split() for line in sweep.stdout.splitlines()[1:]]
    assert len(rows) == 5
    # The contact edge is located within half a contact element (rc / contact_elements).
    half_element = 0.5 * 0.1 / 30
    for row in rows:
        assert abs(float(row[1]) - float(row[2])) < half_element + 1e-5  # + the printed rounding
    figure = tmp_path / "pressure.png"
    drawn = subprocess.run([sys.executable, str(examples / "python" / "pressure_plot.py"), str(figure)],
                           capture_output=True, text=True, env=env)
    assert drawn.returncode == 0, drawn.stderr
    assert figure.read_bytes()[:8] == PNG_SIGNATURE


def _wear_folder(folder, wear=True):
    """A small output folder written by hand: one contact 'contact' of 5 pairs and, with
    `wear`, its wear files over the cycles 1, 2, 4, ..., 1024 (both sides wearing)."""
    folder.mkdir()
    x = np.linspace(-1.0, 1.0, 5)
    files = {"contact.csv": ["x,y,nx,ny,coordinate,p_n,p_t,status"] +
             [f"{v},0,0,1,{v},{-50.0 - 10 * v * v},0,slip" for v in x],
             "contact_steps.csv": ["time,normal_force,a,c,dissipated_energy", "1,100,1,0,0"]}
    if wear:
        cycles = 2.0 ** np.arange(11)
        files["contact_wear.csv"] = [
            "cycle,computed,jump,pressure_change,stable_jump,worn_volume1,worn_volume2,max_depth1,max_depth2,a,"
            "contact_start,contact_end,c,peak_pressure,centre_pressure,pairs_in_contact"] + [
            f"{n:g},{k + 1},{n / 2 if k else 1:g},0.01,300,{1e-6 * n},{5e-7 * n},{1e-6 * n},{5e-7 * n},1,-1,1,"
            f"{0.5 / (1 + k)},{300 / (1 + k)},40,5" for k, n in enumerate(cycles)]
        files["contact_wear_profile.csv"] = ["cycle,pair,x,y,coordinate,depth1,depth2,p_n,p_t,status"] + [
            f"{n:g},{i},{v},0,{v},{1e-6 * n * (1 + v * v)},{5e-7 * n},{-40 - 10 * v * v},0,slip"
            for n in cycles for i, v in enumerate(x[::-1])]
    for name, lines in files.items():
        (folder / name).write_text("\n".join(lines) + "\n")
    summary = {"title": "wear", "outputs": list(files), "results": {"contacts": [{"name": "contact"}]}}
    (folder / "summary.json").write_text(json.dumps(summary))
    return folder


def test_wear_figure_draws_the_scar_over_the_cycles(tmp_path):
    worn = _wear_folder(tmp_path / "worn")
    written = plot.figures(worn)
    assert sorted(p.name for p in written) == ["contact_contact.png", "wear_contact.png"]
    assert (worn / "figures" / "wear_contact.png").read_bytes()[:8] == PNG_SIGNATURE
    fig = plot.wear_figure(plot._load_folder(worn), "contact", "wear")
    depth = _axes_titled(fig, "worn depth")
    # Six cycles spread logarithmically over 1 ... 1024, first and last kept: side 1 solid,
    # side 2 (which wears here) dashed, in the same colour; the profile sorted by coordinate.
    assert [t.get_text() for t in depth.get_legend().get_texts()] == [f"N = {2 ** k}" for k in (0, 2, 4, 6, 8, 10)]
    solid, dashed = depth.get_lines()[-2:]
    assert (solid.get_linestyle(), dashed.get_linestyle()) == ("-", "--")
    np.testing.assert_array_equal(solid.get_xdata(), np.linspace(-1.0, 1.0, 5))
    np.testing.assert_allclose(solid.get_ydata(), 1024e-6 * (1 + np.linspace(-1.0, 1.0, 5) ** 2))
    np.testing.assert_allclose(dashed.get_ydata(), 512e-6)
    pressure_last = _axes_titled(fig, "contact pressure").get_lines()[-1]
    np.testing.assert_allclose(pressure_last.get_ydata(), 40 + 10 * np.linspace(-1.0, 1.0, 5) ** 2)
    volume = _axes_titled(fig, "worn area")
    assert volume.get_xscale() == "log" and len(volume.get_lines()) == 2
    np.testing.assert_allclose(volume.get_lines()[0].get_ydata(), 1e-6 * 2.0 ** np.arange(11))
    assert len(fig.axes) == 5  # c > 0: the stick half-width on a twin axis
    plot.plt.close(fig)
    # A folder without wear files gets no wear figure.
    plain = _wear_folder(tmp_path / "plain", wear=False)
    assert [p.name for p in plot.figures(plain)] == ["contact_contact.png"]


def test_plasticity_figure_draws_the_plastic_zone_and_the_load_curve(examples, binary, tmp_path):
    run_dir = tmp_path / "run"
    text = (examples / "plastic_tube.toml").read_text().replace("size = 0.08", "size = 0.16")
    problem = tmp_path / "tube.toml"
    problem.write_text(text.replace("increments = 20", "increments = 8"))
    bc.run(problem, output=run_dir)
    command = subprocess.run([binary, "plot", str(run_dir)], capture_output=True, text=True)
    assert command.returncode == 0, command.stderr
    assert (run_dir / "figures" / "tube_plasticity.png").read_bytes()[:8] == PNG_SIGNATURE
    result = plot._load_folder(run_dir)
    fig = plot.plasticity_figure(result, "tube", "tube")
    zone = _axes_titled(fig, "equivalent plastic strain")
    polygons = plot.vtk_polygons((run_dir / "tube_cells.vtk").read_text())
    cells = _csv_column(run_dir / "tube_cells.csv", "equivalent_plastic_strain")
    assert len(polygons) == len(cells)
    # The yielded cells' dots are the cells with plastic strain, at their centroids.
    dots = zone.lines[0].get_xydata()
    assert len(dots) == int(np.sum(cells > 0.0)) > 0
    # The curve: the bore's force against its mean displacement along the force (the
    # rollers' reactions do no work), from 0 up to 1.5 p_y and back to 0.
    curve_axes = _axes_titled(fig, "load against displacement")
    assert "'inner'" in curve_axes.get_xlabel()
    curve = curve_axes.lines[0].get_xydata()
    f1 = _csv_column(run_dir / "tube_steps.csv", "inner_f1")
    f2 = _csv_column(run_dir / "tube_steps.csv", "inner_f2")
    np.testing.assert_allclose(curve[1:, 1], np.hypot(f1, f2) * np.sign(f1), rtol=1e-9, atol=1e-12)
    assert curve[0, 0] == 0.0 and curve[-1, 0] > 0.0  # a permanent expansion


def test_plasticity_figure_of_a_ball_indentation_draws_its_curve_and_dent(examples, binary, tmp_path):
    run_dir = tmp_path / "run"
    text = (examples / "brinell.toml").read_text().replace("cell = 0.16", "cell = 0.64")
    problem = tmp_path / "brinell.toml"
    problem.write_text(text.replace("increments = 20", "increments = 6"))
    bc.run(problem, output=run_dir)
    command = subprocess.run([binary, "plot", str(run_dir)], capture_output=True, text=True)
    assert command.returncode == 0, command.stderr
    assert (run_dir / "figures" / "block_plasticity.png").read_bytes()[:8] == PNG_SIGNATURE
    fig = plot.plasticity_figure(plot._load_folder(run_dir), "block", "brinell")
    # The load-depth curve is indentation.csv's, from the origin.
    curve = _axes_titled(fig, "load against displacement").lines[0].get_xydata()
    np.testing.assert_allclose(curve[1:, 0], _csv_column(run_dir / "indentation.csv", "depth"))
    np.testing.assert_allclose(curve[1:, 1], _csv_column(run_dir / "indentation.csv", "load"))
    # The dent: the surface's lowest point is on the axis, as deep as the report says.
    dent = _axes_titled(fig, "the surface after the last step").lines[0].get_xydata()
    summary = json.loads((run_dir / "summary.json").read_text())
    assert dent[0, 0] == 0.0
    assert dent[:, 1].min() == dent[0, 1] == -summary["results"]["indentation"]["residual_depth"]
    plot.plt.close(fig)


def test_the_dent_of_a_coated_block_is_the_coatings_top(examples, tmp_path):
    # examples/brinell_coated.toml: the elastoplastic region is the substrate under the
    # coating; the dent drawn is the indented face (the coating's top), not the bond.
    run_dir = tmp_path / "run"
    text = (examples / "brinell_coated.toml").read_text().replace("cell = 0.32", "cell = 0.64")
    problem = tmp_path / "coated.toml"
    problem.write_text(text.replace("increments = 20", "increments = 6"))
    bc.run(problem, output=run_dir)
    fig = plot.plasticity_figure(plot._load_folder(run_dir), "substrate", "coated")
    dent = _axes_titled(fig, "the surface after the last step").lines[0].get_xydata()
    summary = json.loads((run_dir / "summary.json").read_text())
    assert dent[0, 0] == 0.0
    assert dent[0, 1] == -summary["results"]["indentation"]["residual_depth"]
    assert summary["results"]["indentation"]["elastic_unloading_stiffness"] is None  # a body of two regions
    plot.plt.close(fig)
