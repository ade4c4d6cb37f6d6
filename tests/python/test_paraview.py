"""Every VTK file a run writes, read back by VTK's own readers (what ParaView uses)."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import bemcontact as bc


def read_legacy(path):
    reader = vtkPolyDataReader()
    reader.SetFileName(str(path))
    reader.ReadAllScalarsOn()
    reader.ReadAllVectorsOn()
    reader.ReadAllFieldsOn()
    reader.Update()
    data = reader.GetOutput()
    assert data.GetNumberOfPoints() > 0, path
    return data


def point_array(data, name):
    array = data.GetPointData().GetArray(name)
    assert array is not None, name
    return vtk_to_numpy(array)


def string_field(data, name):
    array = data.GetFieldData().GetAbstractArray(name)
    assert array is not None, name
    return [array.GetValue(i) for i in range(array.GetNumberOfValues())]


def cells(data, kind):
    out = []
    source = {"lines": data.GetLines(), "polys": data.GetPolys(), "verts": data.GetVerts()}[kind]
    ids = vtk_to_numpy(source.GetConnectivityArray())
    offsets = vtk_to_numpy(source.GetOffsetsArray())
    for k in range(len(offsets) - 1):
        out.append(ids[offsets[k]:offsets[k + 1]])
    return out


def test_boundary_lines_carry_the_boundary_names(examples, tmp_path):
    result = bc.run(examples / "plate_hole.toml", output=tmp_path / "out")
    table = result.boundary()
    data = read_legacy(tmp_path / "out" / "boundary.vtk")
    assert data.GetNumberOfPoints() == len(table)
    np.testing.assert_array_equal(point_array(data, "u")[:, 0], table["u1"])
    np.testing.assert_array_equal(point_array(data, "von_mises"), table["von_mises"])
    names = string_field(data, "boundary_names")
    assert set(names) == set(table["boundary"])
    lines = cells(data, "lines")
    piece = vtk_to_numpy(data.GetCellData().GetArray("boundary"))
    assert len(lines) == len(piece) >= len(names)
    # Every node of a line cell, but the one it starts from, is on the named boundary.
    for line, p in zip(lines, piece):
        assert all(table["boundary"][n] == names[p] for n in line[1:])


def test_interior_grid_cells_leave_the_hole_empty(examples, tmp_path):
    problem = bc.Problem.load(examples / "plate_hole.toml")
    result = problem.run(output=tmp_path / "out")
    a = problem.parameters["a"]
    data = read_legacy(tmp_path / "out" / "interior.vtk")
    points = vtk_to_numpy(data.GetPoints().GetData())
    table = result.interior()
    assert len(points) == len(table)
    np.testing.assert_array_equal(point_array(data, "von_mises"), table["von_mises"])
    quads = cells(data, "polys")
    # The 26 x 26 grid of step 0.2: every cell is a square of that side inside the plate.
    assert len(quads) > 500
    for quad in quads:
        corners = points[quad, :2]
        assert np.all(np.hypot(corners[:, 0], corners[:, 1]) >= a)
        sides = np.linalg.norm(np.roll(corners, -1, axis=0) - corners, axis=1)
        np.testing.assert_allclose(sides, 0.2, rtol=1e-9)
    # Exactly the grid squares whose four corners were computed are drawn (the points on
    # the plate's edges x = 0, y = 0 and inside the hole are not): none is missing.
    index = {(round(x / 0.2), round(y / 0.2)): k for k, (x, y) in enumerate(zip(table["x"], table["y"]))}
    expected = {tuple(sorted((index[(i, j)], index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)])))
                for (i, j) in index if {(i + 1, j), (i + 1, j + 1), (i, j + 1)} <= index.keys()}
    assert {tuple(sorted(q)) for q in quads} == expected


def test_contact_pairs_dataset_and_time_series(examples, tmp_path):
    problem = bc.Problem.load(examples / "fretting_cylinder.toml")
    problem = bc.Problem(problem.text.replace("[solver]\n", "[solver]\nrecord_steps = true\n"), problem.file_name)
    out = tmp_path / "out"
    result = problem.run(output=out)
    name = result.contact_names()[0]
    pairs = result.contact(name)
    data = read_legacy(out / f"{name}.vtk")
    assert data.GetNumberOfPoints() == len(pairs)
    np.testing.assert_array_equal(point_array(data, "p_n"), pairs["p_n"])
    status_names = string_field(data, "status_names")
    codes = point_array(data, "status").astype(int)
    assert [status_names[c] for c in codes] == list(pairs["status"])
    steps = result.contact_steps(name)
    # Every recorded step's files are in steps/, the time series at the top.
    per_step = [f for f in result.names() if "_step" in f and not f.endswith("_steps.csv")]
    assert per_step and all(f.startswith("steps/") for f in per_step)
    assert sorted(p.name for p in (out / "steps").iterdir()) == sorted(f[len("steps/"):] for f in per_step)
    series = [f for f in result.names() if f.endswith(".pvd")]
    assert f"{name}.pvd" in series and len(series) == 3  # the pairs and the two bodies' boundaries
    for pvd in series:
        entries = ET.parse(out / pvd).getroot().findall("./Collection/DataSet")
        times = [float(e.get("timestep")) for e in entries]
        assert times == sorted(times) and len(times) == len(steps)
        np.testing.assert_allclose(times, steps["time"])
        for entry in entries:
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(str(out / entry.get("file")))
            reader.Update()
            step = reader.GetOutput()
            if pvd == f"{name}.pvd":  # the pairs of that step, as in <contact>_step<k>.csv
                k = int(entry.get("file").rsplit("_step", 1)[1].split(".")[0])
                pairs_k = result.contact_step(k, name)
                assert step.GetNumberOfVerts() == step.GetNumberOfPoints() == len(pairs_k)
                np.testing.assert_allclose(point_array(step, "p_n"), pairs_k["p_n"], rtol=1e-15)
                continue
            assert step.GetNumberOfPoints() > 0 and step.GetNumberOfLines() > 0
            assert step.GetCellData().GetArray("boundary") is not None
            assert step.GetPointData().GetArray("u") is not None


def test_every_vtk_file_of_every_kind_reads_back(examples, tmp_path):
    from vtkmodules.vtkIOLegacy import vtkDataSetReader

    text = (examples / "fretting_cylinder.toml").read_text().replace("[solver]\n", "[solver]\nrecord_steps = true\n")
    runs = [bc.run(examples / "plate_hole.toml"), bc.run(examples / "dd_two_layer_ring.toml"),
            bc.run(examples / "contact_roller_plates.toml"), bc.Problem(text, "fretting.toml").run(),
            bc.Problem.load(examples / "contact_roller_plates.toml").mesh(),
            bc.Problem.load(examples / "plate_hole.toml").mesh()]
    read = 0
    for k, result in enumerate(runs):
        folder = result.save(tmp_path / f"run{k}")
        for name in result.names():
            path = folder / name
            if name.endswith(".vtk"):
                reader = vtkDataSetReader()
                reader.SetFileName(str(path))
                reader.ReadAllScalarsOn()
                reader.ReadAllVectorsOn()
                reader.Update()
                data = reader.GetOutput()
                declared = int(result.text(name).split("POINTS ")[1].split()[0])
            elif name.endswith(".vtp"):
                reader = vtkXMLPolyDataReader()
                reader.SetFileName(str(path))
                reader.Update()
                data = reader.GetOutput()
                declared = int(result.text(name).split('NumberOfPoints="')[1].split('"')[0])
            else:
                continue
            assert data is not None and data.GetNumberOfPoints() == declared > 0, name
            assert data.GetNumberOfCells() > 0, name
            read += 1
    assert read >= 15
