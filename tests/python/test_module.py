"""The Python module against closed forms, the command line and its own contracts."""
import hashlib
import json
import math
import re
import subprocess

import numpy as np
import pytest

import bemcontact as bc


def tension_plate(E=200.0, nu=0.3, p=2.0, width=2.0, height=1.0):
    """A plane-stress plate pulled on its right edge, held by symmetry on two edges."""
    return {
        "title": "plate in tension from Python",
        "analysis": "plane_stress",
        "interpolation": "linear",
        "parameters": {"p": p, "W": width, "H": height},
        "material": {"E": E, "nu": nu},
        "vertices": {"A": [0.0, 0.0], "B": ["W", 0.0], "C": ["W", "H"], "D": [0.0, "H"]},
        "boundary": [
            {"name": "bottom", "from": "A", "to": "B", "elements": 4, "u2": 0.0, "t1": 0.0},
            {"name": "right", "from": "B", "to": "C", "elements": 3, "t1": "p", "t2": 0.0},
            {"name": "top", "from": "C", "to": "D", "elements": 4},
            {"name": "left", "from": "D", "to": "A", "elements": 3, "u1": 0.0, "t2": 0.0},
        ],
        "interior": {"points": [[0.5, 0.5], [1.5, 0.25]]},
    }


def test_uniform_tension_matches_the_closed_form():
    # A linear field is reproduced exactly by linear elements: round-off only.
    E, nu, p = 200.0, 0.3, 2.0
    result = bc.Problem.from_dict(tension_plate(E, nu, p)).run()
    inner = result.interior()
    assert list(inner["point"]) == [0.0, 1.0]
    np.testing.assert_allclose(inner["s11"], p, rtol=1e-6)
    np.testing.assert_allclose(inner["s22"], 0.0, atol=1e-6 * p)
    np.testing.assert_allclose(inner["u1"], p / E * inner["x"], rtol=1e-6)
    np.testing.assert_allclose(inner["u2"], -nu * p / E * inner["y"], rtol=1e-6)
    edge = result.boundary()
    on_right = edge["boundary"] == "right"
    assert on_right.sum() > 0
    np.testing.assert_allclose(edge["u1"][on_right], p / E * 2.0, rtol=1e-6)


def hertz_sphere_radius(problem, force):
    """a = (3 P R / 4 E*)^(1/3), E* from the two bodies of the example (closed form)."""
    data = problem.data()
    nu = data["body"][0]["material"]["nu"]
    E1 = problem.parameters["E_ball"]
    E2 = data["body"][1]["material"]["E"]
    E_star = 1.0 / ((1 - nu**2) / E1 + (1 - nu**2) / E2)
    return (3.0 * force * problem.parameters["R"] / (4.0 * E_star)) ** (1.0 / 3.0)


def test_parameter_sweep_follows_hertz(examples):
    problem = bc.Problem.load(examples / "contact_hertz_sphere.toml")
    h = problem.parameters["rc"] / problem.parameters["contact_elements"]
    for force in (15.0, 31.5, 63.0):
        result = problem.run(P=force)
        a = result.summary["results"]["contact"]["a"]
        reference = hertz_sphere_radius(problem, force)
        # The contact edge is located within half an element.
        assert abs(a - reference) < 0.5 * h, (force, a, reference)
        pairs = result.contact()
        assert pairs.columns[:3] == ["pair", "x", "y"]
        assert np.all(pairs["p_n"] <= 0.0)
        assert set(pairs["status"]) <= {"stick", "slip", "open"}
        # The pressures balance the applied force (whole ring: 2 pi r dr).
        assert result.summary["results"]["contact"]["normal_force"] == pytest.approx(force, rel=1e-3)


def test_a_zone_found_from_candidates_follows_the_load(examples):
    """The README's demo from candidate surfaces: loads 13 times apart from one file, each
    zone resolved to the asked spacing, a within 1 % of Hertz (validate zone-growth)."""
    problem = bc.Problem.load(examples / "contact_hertz_sphere_adaptive.toml")
    for force in (31.5, 400.0):
        result = problem.run(P=force)
        contact = result.summary["results"]["contacts"][0]
        last = contact["zone"]["passes"][-1]
        assert last["resolved"] and last["edge_spacing"] <= 0.02 * last["width"]
        assert len(contact["zone"]["breakpoints1"]) == 1  # one list per boundary of the side
        assert len(contact["zone"]["breakpoints1"][0]) == last["elements1"] + 1
        reference = hertz_sphere_radius(problem, force)
        assert contact["a"] == pytest.approx(reference, rel=0.01)


def test_version_agrees_with_the_command_and_the_summary(binary, examples):
    shown = subprocess.run([binary, "--version"], capture_output=True, text=True, check=True).stdout.split()
    assert shown == ["bemcontact", bc.__version__]
    result = bc.run(examples / "plate_tension.toml")
    assert result.summary["bemcontact_version"] == bc.__version__


def test_errors_raise_with_the_command_line_messages(examples, binary, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text((examples / "plate_tension.toml").read_text().replace("nu = 0.1", "nu = 0.1\nnuu = 3"))
    with pytest.raises(bc.InputError) as raised:
        bc.run(bad)
    message = str(raised.value)
    assert str(bad) in message and "nuu" in message
    command = subprocess.run([binary, "run", str(bad), "-o", str(tmp_path / "out")], capture_output=True, text=True)
    assert command.returncode == 2
    assert message in command.stderr
    with pytest.raises(bc.InputError) as unknown:
        bc.run(examples / "plate_tension.toml", Q=1.0)
    # Named as the caller wrote it: a keyword argument, not the command line's --set.
    assert "keyword argument Q=1: the file has no parameter 'Q'" in str(unknown.value)
    assert "--set" not in str(unknown.value)
    assert issubclass(bc.GeometryError, bc.Error) and issubclass(bc.SolverError, bc.Error)
    crossing = tension_plate()
    crossing["vertices"]["C"] = [0.0, "H"]
    crossing["vertices"]["D"] = ["W", "H"]
    with pytest.raises(bc.GeometryError):
        bc.Problem.from_dict(crossing).run()


def test_parameters_take_expressions_as_the_file_writes_them(examples):
    # P = "2*74" is P = 148; an expression may use the parameters written before it in the
    # file (rc after R), and the expressions after it see the new value (theta = asin(rc/R)).
    problem = bc.Problem.load(examples / "fretting_cylinder.toml")
    number = problem.run(P=148.0, rc=0.085, n=10)
    for expression in (problem.run(P="2*74", rc="0.085*R", n="5*2"),
                       bc.run(examples / "fretting_cylinder.toml", P="2 * 74", rc="0.085 * R", n="10"),
                       problem.with_parameters(P="2*74").run(rc="0.085*R", n=10)):
        assert expression.summary["parameters"] == number.summary["parameters"]
        assert expression.summary["parameters"]["theta"] == pytest.approx(math.asin(0.085), rel=1e-15)
        for name in ("contact.csv", "motions.csv", "cylinder_boundary.csv"):
            assert expression.text(name) == number.text(name), name
    assert problem.with_parameters(P="2*74").parameters["P"] == "2*74"  # as given, evaluated by run


@pytest.mark.parametrize("value, says", [
    ("2*", "keyword argument P='2*': in expression \"2*\", column 3"),
    ("1/0", "keyword argument P='1/0': the value is inf"),
    ("x + 1", "keyword argument P='x + 1': in expression"),
    ("2*Pmax", "keyword argument P='2*Pmax': in expression \"2*Pmax\", column 3: unknown name 'Pmax'"),
    ("mu * 500", "keyword argument P='mu * 500': parameter 'P' uses 'mu', which is defined later"),
    (math.nan, "keyword argument P=nan: the value is nan"),
])
def test_a_bad_parameter_value_names_the_parameter(examples, value, says):
    path = examples / "fretting_cylinder.toml"
    line = next(k for k, text in enumerate(path.read_text().splitlines(), 1) if text.startswith("P = "))
    with pytest.raises(bc.InputError) as raised:
        bc.run(path, P=value)
    message = str(raised.value)
    assert f"{path}:{line}: key 'parameters.P': " in message and says in message, message


def test_a_parameter_value_must_be_a_number_or_an_expression(examples):
    for value, kind in (([1.0], "list"), (True, "bool"), (None, "NoneType")):
        with pytest.raises(bc.InputError, match=re.escape(f"keyword argument P={value!r}: ") + f".* found {kind}$"):
            bc.run(examples / "fretting_cylinder.toml", P=value)
    with pytest.raises(bc.InputError, match="keyword argument rc='2\\*theta': parameter 'rc' uses 'theta', which "
                                            "is defined later"):
        bc.run(examples / "fretting_cylinder.toml", rc="2*theta")
    assert bc.Problem.load(examples / "fretting_cylinder.toml").with_parameters(n=np.int64(12)).parameters["n"] == 12.0


def test_results_are_the_files_of_the_command_line(examples, binary, tmp_path):
    command_dir = tmp_path / "command"
    subprocess.run([binary, "run", str(examples / "contact_roller_plates.toml"), "-q", "-o", str(command_dir)],
                   check=True)
    result = bc.run(examples / "contact_roller_plates.toml", threads=2)
    written = sorted(p.name for p in command_dir.iterdir() if not p.name.startswith("."))
    assert sorted(result.names()) == written
    for name in written:
        if name != "summary.json":  # timings differ
            assert result.text(name) == (command_dir / name).read_text(), name
    assert result.contact_names() == ["bottom", "top"]
    with pytest.raises(KeyError, match="bottom, top"):
        result.contact()
    steps = result.contact_steps("top")
    assert steps["time"][-1] == pytest.approx(1.0)
    with pytest.raises(KeyError, match="bottom_plate"):
        result.boundary()
    assert len(result.boundary("roller")) > 0


def test_wear_tables_follow_the_cycles(examples):
    result = bc.run(examples / "wear_punch_gross_slip.toml", N=1000, n=20)
    cycles = result.wear()
    assert cycles["cycle"][0] == 1 and cycles["cycle"][-1] == 1000
    assert np.all(np.diff(cycles["worn_volume1"]) > 0) and np.all(cycles["worn_volume2"] == 0)
    scar = result.wear(profile=True)
    last = scar["cycle"] == 1000
    assert np.max(scar["depth1"][last]) == pytest.approx(cycles["max_depth1"][-1])
    with pytest.raises(KeyError, match="does not wear"):
        bc.run(examples / "fretting_cylinder.toml", n=10).wear()


def test_motions_are_named_by_body_and_direction(examples):
    fretting = bc.run(examples / "fretting_cylinder.toml", n=20).motions()
    assert fretting.columns == ["step", "time", "cylinder_P_force", "cylinder_P_displacement", "cylinder_Q_force",
                                "cylinder_Q_displacement"]
    # The roller is held only by the plates: its rigid motion, half the top platen's approach
    # (the model is its own mirror image about the roller's centre line).
    roller = bc.run(examples / "contact_roller_plates.toml").motions()
    assert roller.columns == ["step", "time", "top_plate_top_y_force", "top_plate_top_y_displacement",
                              "roller_y_displacement"]
    np.testing.assert_allclose(roller["roller_y_displacement"], 0.5 * roller["top_plate_top_y_displacement"],
                               rtol=1e-9)


def test_save_replaces_the_folder_whole(examples, tmp_path):
    out = tmp_path / "run"
    bc.run(examples / "contact_roller_plates.toml", output=out)
    assert (out / "top.csv").exists()
    bc.run(examples / "plate_tension.toml", output=out)
    names = sorted(p.name for p in out.iterdir())
    assert "top.csv" not in names and "boundary.csv" in names
    assert json.loads((out / "summary.json").read_text())["title"].startswith("Plate in uniaxial tension")


def test_mesh_only(examples):
    result = bc.Problem.load(examples / "contact_roller_plates.toml").mesh()
    assert any(name.endswith("_pairs.csv") for name in result.names())
    assert "summary.json" in result.names()


def test_dictionary_round_trip_is_the_same_problem():
    data = tension_plate()
    problem = bc.Problem.from_dict(data)
    assert problem.data() == json.loads(json.dumps(data))
    assert problem.parameters == {"p": 2.0, "W": 2.0, "H": 1.0}
    assert problem.with_parameters(p=3).parameters["p"] == 3.0
    with pytest.raises(ValueError):
        bc.Problem.from_dict({"parameters": {"x": math.nan}})


def test_one_summary_schema_for_every_kind_and_command(examples):
    keys = None
    for name, kind in (("plate_tension.toml", "body"), ("dd_two_layer_ring.toml", "decomposition"),
                       ("contact_hertz_sphere.toml", "contact")):
        problem = bc.Problem.load(examples / name)
        for command, result in (("run", problem.run()), ("mesh", problem.mesh())):
            s = result.summary
            assert (s["schema"], s["kind"], s["command"]) == ("bemcontact.summary/1", kind, command)
            keys = keys or set(s)
            assert set(s) == keys, name
            assert s["input"]["file"] == str(examples / name)
            assert s["input"]["sha256"] == hashlib.sha256(problem.text.encode()).hexdigest()
            assert s["bemcontact_version"] == bc.__version__
            assert s["outputs"] == [n for n in result.names() if n != "summary.json"]
            regions = s["mesh"]["regions"].values()
            assert s["mesh"]["nodes"] == sum(r["nodes"] for r in regions) > 0
            if command == "run":
                assert s["reactions"] and s["timings_seconds"]["total"] > 0


@pytest.mark.skipif(not bc._core.reads_geo_files, reason="built without the Gmsh library")
def test_gmsh_geometry_gives_the_problem_drawn_by_hand(examples):
    # gmsh_plate_hole.geo draws plate_hole.toml's boundary (two curves against the body's
    # orientation): the same nodes and stresses to round-off.
    by_hand = bc.run(examples / "plate_hole.toml")
    drawn = bc.run(examples / "gmsh_plate_hole.toml")
    for a, b in ((by_hand.boundary(), drawn.boundary()), (by_hand.interior(), drawn.interior())):
        np.testing.assert_allclose(b["x"], a["x"], atol=1e-12)
        np.testing.assert_allclose(b["von_mises"], a["von_mises"], rtol=1e-9, atol=1e-9 * a["von_mises"].max())
    # Kirsch: s_tt = 3P at (a, 0) (the finite plate adds about 0.3 %, the mesh about 1 %).
    P = 2.5
    edge = drawn.boundary()
    at_a = np.argmin(np.hypot(edge["x"] - 1.0, edge["y"]))
    assert edge["s22"][at_a] == pytest.approx(3 * P, rel=0.02)


@pytest.mark.skipif(not bc._core.reads_geo_files, reason="built without the Gmsh library")
def test_geo_numbers_threads_and_timeout(tmp_path):
    # A keyword for no parameter of the file goes to the .geo's DefineConstant; the run keeps
    # its threads; a .geo that does not end stops at gmsh_timeout.
    (tmp_path / "strip.geo").write_text(
        "DefineConstant[ W = 2 ];\nPoint(1) = {0, 0, 0};\nPoint(2) = {W, 0, 0};\nPoint(3) = {W, 1, 0};\n"
        "Point(4) = {0, 1, 0};\nLine(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 1};\n"
        "Physical Curve(\"bottom\") = {1};\nPhysical Curve(\"right\") = {2};\nPhysical Curve(\"top\") = {3};\n"
        "Physical Curve(\"left\") = {4};\n")
    problem = bc.Problem.from_dict({"analysis": "plane_stress", "geometry": "strip.geo",
                                    "material": {"E": 1.0, "nu": 0.3},
                                    "boundary": [{"name": "left", "u1": 0.0, "u2": 0.0},
                                                 {"name": "right", "t1": 1.0}]},
                                   name=str(tmp_path / "strip.toml"))
    result = problem.run(threads=2, W=3.0)
    assert result.boundary()["x"].max() == pytest.approx(3.0)
    assert result.summary["options"]["threads"] == 2 and result.summary["parameters"]["W"] == 3.0
    (tmp_path / "endless.geo").write_text("Point(1) = {0, 0, 0};\nFor i In {1:1e15}\nEndFor\n")
    endless = bc.Problem('analysis = "plane_stress"\ngeometry = "endless.geo"\n[material]\nE = 1.0\nnu = 0.3\n',
                         str(tmp_path / "endless.toml"))
    with pytest.raises(bc.InputError, match="did not finish meshing the file within 0.3 s"):
        endless.mesh(gmsh_timeout=0.3)


def test_probe_gives_the_runs_interior_points_and_the_command_lines_files(binary, tmp_path):
    # The same Somigliana integrals on the same boundary values: the run's interior points
    # exactly; a uniform field on a line; and the files `bemcontact probe` writes.
    result = bc.Problem.from_dict(tension_plate()).run()
    inner = result.interior()
    table = result.probe(points=np.column_stack([inner["x"], inner["y"]]), lines=[(0.0, 0.5, 2.0, 0.5, 5)])
    listed = table["line"] == 0
    for column in ("u1", "u2", "s11", "s22", "s12", "s33"):
        np.testing.assert_array_equal(table[column][listed], inner[column])
    on_line = table["line"] == 1
    assert on_line.sum() == 5
    assert table["on_boundary"][on_line].tolist() == [1, 0, 0, 0, 1]
    np.testing.assert_allclose(table["s11"][on_line], 2.0, rtol=1e-6)
    assert list(table["body"]) == ["body"] * 7
    assert table.summary["rows"] == 7 and table.warnings == []
    result.save(tmp_path / "run")
    subprocess.run([binary, "probe", str(tmp_path / "run"), "--line", "0,0.5,2,0.5,5", "-q"], check=True)
    alone = result.probe(lines=[(0, 0.5, 2, 0.5, 5)])
    assert (tmp_path / "run" / "probe" / "probe.csv").read_bytes() == alone.files["probe.csv"]


def test_probe_errors_name_the_point_and_warn_for_lines(tmp_path):
    result = bc.Problem.from_dict(tension_plate()).run()
    with pytest.raises(bc.InputError, match=r"<points>:2: point \(5, 0.5\) lies inside no body"):
        result.probe(points=[(1.0, 0.5), (5.0, 0.5)])
    with pytest.raises(bc.InputError, match=r"lines\[0\]"):
        result.probe(lines=[(0, 0, 1, 1, 1)])
    table = result.probe(lines=[(-1.0, 0.5, 1.0, 0.5, 5)], output=tmp_path / "probe")
    assert len(table) == 3 and "2 of its 5 points are inside no body" in table.warnings[0]
    assert (tmp_path / "probe" / "probe.vtk").exists()


def test_probe_and_run_arguments_are_checked_before_any_work():
    # A wrong shape is not read as other points, a line of 10^9 points is refused before it
    # is made, and the Python layer's errors carry the attributes the native ones do.
    result = bc.Problem.from_dict(tension_plate()).run()
    with pytest.raises(bc.InputError, match=r"shape \(2, 3\)") as wrong_shape:
        result.probe(points=[(0, 1, 0), (0.5, 0.5, 0)])
    assert wrong_shape.value.key == "points" and wrong_shape.value.file == "probe()" and wrong_shape.value.line is None
    assert len(result.probe(points=(1.0, 0.5))) == 1  # one point as a pair
    with pytest.raises(bc.InputError, match=r"over the limit of 2000000 \(raise it with max_points=\)"):
        result.probe(lines=[(-0.5, 1, 0.5, 1, 10**9)])
    for line in [(0, 0, 1, 1, math.inf), (0, 0, 1, 1, math.nan), (0, 0, 1, 1), ("a", 0, 1, 1, 3)]:
        with pytest.raises(bc.InputError, match=r"lines\[0\]") as bad_line:
            result.probe(lines=[line])
        assert bad_line.value.key == "lines[0]" and bad_line.value.detail
    with pytest.raises(bc.InputError, match=r"probe\(\).*points=") as none:
        result.probe()
    assert none.value.file == "probe()"
    problem = bc.Problem.from_dict(tension_plate())
    for bad in (-1.0, 0.0, math.nan, "a"):
        with pytest.raises(bc.InputError, match="gmsh_timeout"):
            problem.run(gmsh_timeout=bad)
    for bad in (-5, 1.5, "a", True):
        with pytest.raises(bc.InputError, match="threads") as threads:
            problem.run(threads=bad)
        assert threads.value.key == "threads"
    with pytest.raises(bc.InputError) as keyword:
        problem.run(p=[1])
    assert keyword.value.key == "p" and keyword.value.file == "keyword argument"
    # threads=1 for one run does not stay for the next (threads=0: every core, or
    # OMP_NUM_THREADS).
    every = problem.run().summary["options"]["threads"]
    assert problem.run(threads=1).summary["options"]["threads"] == 1
    assert problem.run().summary["options"]["threads"] == every


def test_errors_carry_their_data(examples, tmp_path):
    # An input error's place, a geometry error's boundaries, a solver failure's part.
    with pytest.raises(bc.InputError) as raised:
        bc.run(examples / "plate_tension.toml", P="1/0")
    assert raised.value.file.endswith("plate_tension.toml") and raised.value.line > 0
    assert raised.value.key == "parameters.P" and "finite" in raised.value.detail
    crossing = bc.Problem.from_dict({"analysis": "plane_stress", "material": {"E": 1.0, "nu": 0.3},
                                     "vertices": {"A": [0.0, 0.0], "B": [1.0, 1.0], "C": [1.0, 0.0], "D": [0.0, 1.0]},
                                     "boundary": [{"name": "ab", "from": "A", "to": "B"},
                                                  {"name": "bc", "from": "B", "to": "C"},
                                                  {"name": "cd", "from": "C", "to": "D"},
                                                  {"name": "da", "from": "D", "to": "A"}]},
                                    name=str(tmp_path / "cross.toml"))
    with pytest.raises(bc.GeometryError) as bad_geometry:
        crossing.run()
    assert bad_geometry.value.places and bad_geometry.value.places[0][0].endswith("cross.toml")
    ball = bc.Problem.load(examples / "contact_hertz_sphere.toml")
    with pytest.raises(bc.SolverError) as clipped:
        ball.run(P=400.0)
    assert clipped.value.part == "contact zone" and clipped.value.step == 1 and clipped.value.time == 1.0
    assert clipped.value.iterations is None
