"""A result's tables are the run's own values: numpy arrays made from the C++ columns the CSV
files were written from (no CSV text read back), equal to the files' numbers."""
import csv
import io

import numpy as np
import pytest

import bemcontact as bc


def file_columns(text):
    """The header and the columns of a CSV text, as strings."""
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], [[row[k] for row in rows[1:]] for k in range(len(rows[0]))]


def refuse_parsing(monkeypatch):
    def parse(name, text):
        raise AssertionError(f"{name}: the CSV text was parsed")
    monkeypatch.setattr(bc, "_parse_csv", parse)


def check_table(table, text, name):
    header, columns = file_columns(text)
    assert table.columns == header, name
    assert len(table) == len(columns[0]), name
    for column, written in zip(header, columns):
        values = table[column]
        if values.dtype.kind == "U":  # a text column (boundary, status, body, ...)
            assert list(values) == written, (name, column)
            continue
        assert values.dtype == np.float64 and not values.flags.writeable, (name, column)
        if len(values):  # the C++ vector itself, owned by the array's base
            assert type(values.base).__name__ == "PyCapsule", (name, column)
        # Every number is written with the shortest text that reads back as the same double,
        # so the file's numbers are the arrays bit for bit; only a zero's sign may differ (-0
        # is written "0" in most files): zeros compare by value.
        parsed = np.array([float(v) for v in written], dtype=np.float64)
        assert np.array_equal(values, parsed), (name, column)
        nonzero = parsed != 0.0
        assert np.array_equal(values[nonzero].view(np.uint64), parsed[nonzero].view(np.uint64)), (name, column)


def check_tables(result):
    names = [name for name in result.files if name.endswith(".csv")]
    assert names
    for name in names:
        check_table(result.table(name), result.text(name), name)
    return names


@pytest.mark.parametrize("example", ["plate_hole.toml", "dd_strips_3.toml", "fretting_cylinder.toml"])
def test_tables_of_runs_and_meshes_are_the_files_numbers(examples, monkeypatch, example):
    problem = bc.Problem.load(examples / example)
    run, mesh = problem.run(), problem.mesh()
    refuse_parsing(monkeypatch)
    check_tables(run)
    check_tables(mesh)


def test_recorded_steps_and_probe_tables(examples, monkeypatch):
    path = examples / "contact_punch_halfplane.toml"
    unilateral = 'kind = "unilateral"'
    text = path.read_text().replace(unilateral, unilateral + "\nrecord_steps = true\nincrements = 2", 1)
    result = bc.Problem(text, str(path)).run()
    refuse_parsing(monkeypatch)
    names = check_tables(result)
    assert "steps/contact_step2.csv" in names
    assert len(result.contact_step(np.int64(2))) == len(result.contact_step(2))
    with pytest.raises(TypeError, match="whole number"):
        result.contact_step(1.7)  # not read as step 1
    probe = result.probe(lines=[(0.0, -0.1, 0.0, -0.5, 5)])
    check_table(probe, probe.files["probe.csv"].decode(), "probe.csv")
    assert len(probe) == 5 and probe["body"].dtype.kind == "U"


def test_a_folder_read_back_gives_the_same_tables(examples):
    result = bc.run(examples / "plate_hole.toml")
    # As bemcontact.plot reads a run's folder: the files alone, parsed.
    folder = bc.Result({"files": result.files, "report": "", "warnings": [], "solver_failure": ""})
    for name in ("boundary", "interior"):
        ours, parsed = result.table(name), folder.table(name)
        assert ours.columns == parsed.columns and len(ours) == len(parsed)
        for column in ours.columns:
            np.testing.assert_array_equal(ours[column], parsed[column])
        assert parsed["x"].flags.writeable  # (parsed: the reader's own arrays)
