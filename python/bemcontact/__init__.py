"""bemcontact from Python: load or build a problem, run it, read every result as arrays.

    import bemcontact as bc
    problem = bc.Problem.load("examples/contact_hertz_sphere.toml")
    result = problem.run(P=40.0)               # [parameters] overridden by name
    print(result.summary["results"]["contact"]["a"])  # summary.json (docs/summary.md)
    pairs = result.contact()                   # contact.csv as numpy columns
    print(pairs["x"], pairs["p_n"])

Errors raise bemcontact.InputError / GeometryError / SolverError (all bemcontact.Error)
with the messages of the command line. See docs/python.md.
"""
import csv
import hashlib
import io
import json
import numbers
import os
import tomllib

import numpy as np

from . import _toml
from ._core import Error, GeometryError, InputError, SolverError, __version__
from . import _core

__all__ = ["Problem", "Result", "Table", "run", "Error", "InputError", "GeometryError", "SolverError",
           "__version__"]


class Table(dict):
    """One CSV file: column name -> numpy array (float64, or str for text columns such as
    `boundary` or `status`), in the file's column order.

    `data` is the file's columns as the run made them, [(name, values)] (numbers as numpy
    arrays, text as lists of str: a result's tables, nothing parsed), or the CSV text (a
    run's folder read from disk)."""

    def __init__(self, name, data):
        super().__init__()
        self.name = name
        columns = _parse_csv(name, data) if isinstance(data, str) else data
        self.columns = [column for column, _ in columns]
        for column, values in columns:
            self[column] = values if isinstance(values, np.ndarray) else np.array(values, dtype=str)

    def __len__(self):
        return len(next(iter(self.values()))) if self.columns else 0

    def rows(self):
        return len(self)

    def __repr__(self):
        return f"Table({self.name!r}, {len(self)} rows, columns={self.columns})"


def _parse_csv(name, text):
    """A CSV file's columns read from its text: a column of numbers as a float array, any
    other as str."""
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        raise ValueError(f"{name} is empty")
    columns = []
    for k, column in enumerate(rows[0]):
        values = [row[k] for row in rows[1:]]
        try:
            columns.append((column, np.array([float(v) for v in values], dtype=float)))
        except ValueError:
            columns.append((column, np.array(values, dtype=str)))
    return columns


class Result:
    """The files of one run, in memory: `summary` (summary.json), `report` (the terminal
    summary), `warnings`, and every CSV as a Table (from the run's own values)."""

    def __init__(self, raw):
        self.files = dict(raw["files"])
        # Each CSV file's columns as the run computed them (numpy arrays, read-only, shared by
        # every table() of the file); none for a result read back from a folder.
        self._tables = dict(raw.get("tables", {}))
        self.report = raw["report"]
        self.warnings = list(raw["warnings"])
        self.solver_failure = raw["solver_failure"]
        self.summary = json.loads(self.files["summary.json"]) if "summary.json" in self.files else {}

    def names(self):
        return list(self.files)

    def text(self, name):
        if name not in self.files:
            raise KeyError(f"no file '{name}' in this result; files: {', '.join(self.files)}")
        return self.files[name].decode()

    def table(self, name):
        """A CSV file by name, with or without '.csv': the run's own arrays (the file's text is
        read only for a result loaded from a folder)."""
        name = name if name.endswith(".csv") else name + ".csv"
        if name in self._tables:
            return Table(name, self._tables[name])
        return Table(name, self.text(name))

    def _per_body(self, suffix, body):
        if body is not None:
            return self.table(f"{body}_{suffix}")
        if f"{suffix}.csv" in self.files:
            return self.table(suffix)
        found = [n for n in self.files if n.endswith(f"_{suffix}.csv")]
        if len(found) == 1:
            return self.table(found[0])
        bodies = ", ".join(n[: -len(f"_{suffix}.csv")] for n in found) or "none"
        raise KeyError(f"name the body: {suffix} files exist for {bodies}")

    def boundary(self, body=None):
        """Boundary nodes: x, y, normal, u, t, stresses, von_mises, boundary name."""
        return self._per_body("boundary", body)

    def interior(self, body=None):
        """Interior points: x, y, u, stresses, von_mises."""
        return self._per_body("interior", body)

    def contact_names(self):
        return [c["name"] for c in self.summary.get("results", {}).get("contacts", [])]

    def _contact_name(self, name):
        names = self.contact_names()
        if name is None:
            if len(names) != 1:
                raise KeyError(f"name the contact: this result has {', '.join(names) or 'none'}")
            return names[0]
        if name not in names:
            raise KeyError(f"no contact '{name}'; contacts: {', '.join(names) or 'none'}")
        return name

    def contact(self, name=None):
        """Contact pairs at the end of the history: x, y, gap, p_n, p_t, slip, status."""
        return self.table(self._contact_name(name))

    def contact_steps(self, name=None):
        """One row per load step: time, a, c, stick zone, forces, energy, iterations."""
        return self.table(self._contact_name(name) + "_steps")

    def contact_step(self, step, name=None):
        """The pairs at load step `step` (1 = first), written with record_steps = true."""
        if isinstance(step, (bool, np.bool_)) or not isinstance(step, numbers.Integral):
            raise TypeError(f"step={step!r}: a load step is a whole number from 1")
        table = f"steps/{self._contact_name(name)}_step{int(step)}"
        if table + ".csv" not in self.files:
            raise KeyError(f"no pairs of step {step}: run with record_steps = true in [solver] "
                           f"({len(self.contact_steps(name))} steps in this result)")
        return self.table(table)

    def motions(self):
        """Rigid-body and platen motions and forces per step."""
        return self.table("motions")

    def wear(self, name=None, profile=False):
        """A wearing contact's computed load cycles (cycles each stands for, worn volumes,
        deepest points, contact zone, peak pressure), or with profile=True its scar pair by pair
        per computed cycle (depth1, depth2, p_n, p_t, status)."""
        contact = self._contact_name(name)
        table = contact + ("_wear_profile" if profile else "_wear")
        if table + ".csv" not in self.files:
            raise KeyError(f"contact '{contact}' does not wear: give it wear_coefficient1 or "
                           f"wear_coefficient2 (docs/contact.md, Wear)")
        return self.table(table)

    def probe(self, points=(), lines=(), output=None, threads=0, max_points=2_000_000):
        """Displacements and stresses at new points, from this result's boundary solution (no
        new solve), as `bemcontact probe`: `points` a sequence of (x, y) or an (n, 2) array,
        `lines` of (x0, y0, x1, y1, n) (n points, ends included), at most `max_points` points
        in all (as --max-points). Returns probe.csv as a Table (a row per point and body
        holding it), with `.warnings` (points of lines inside no body, left out), `.summary`
        (probe.json) and `.files`; `output` also writes the files there (the folder replaced
        whole). A listed point inside no body is an InputError naming its place in the list
        (from 1)."""
        try:
            array = np.asarray(points, dtype=float)
        except (TypeError, ValueError):
            raise _argument_error("probe()", "points", f"{points!r} is not a sequence of (x, y) pairs") from None
        if array.size == 0:
            array = array.reshape(0, 2)
        elif array.shape == (2,):
            array = array.reshape(1, 2)  # one point
        if array.ndim != 2 or array.shape[1] != 2:
            raise _argument_error("probe()", "points", f"a sequence of (x, y) pairs or an (n, 2) array, found shape "
                                  f"{array.shape}")
        if not np.all(np.isfinite(array)):
            raise _argument_error("probe()", "points", "every coordinate must be a finite number")
        points = [(float(x), float(y)) for x, y in array]
        checked = []
        for k, line in enumerate(lines):
            what = "a line is (x0, y0, x1, y1, n) with n >= 2 points (a whole number, ends included) and two " \
                   "different finite ends"
            try:
                x0, y0, x1, y1, n = (float(v) for v in line)
            except (TypeError, ValueError):
                raise _argument_error("probe()", f"lines[{k}]", f"{line!r}: {what}") from None
            if not (np.all(np.isfinite([x0, y0, x1, y1, n])) and n == int(n) and n >= 2 and (x0, y0) != (x1, y1)):
                raise _argument_error("probe()", f"lines[{k}]", f"{tuple(line)!r}: {what}")
            if n > max_points:
                raise _argument_error("probe()", f"lines[{k}]", f"{int(n)} points, over the limit of {max_points} "
                                      f"(raise it with max_points=)")
            checked.append((x0, y0, x1, y1, int(n)))
        raw = _core.probe(self.files, points, checked, _thread_count("probe()", threads), int(max_points))
        table = Table("probe.csv", raw["tables"]["probe.csv"])
        table.files = dict(raw["files"])
        table.warnings = list(raw["warnings"])
        table.summary = json.loads(table.files["probe.json"])
        if output is not None:
            _core.commit(table.files, os.fspath(output))
        return table

    def save(self, directory):
        """Write the files to `directory`, replacing it whole (as `bemcontact run -o`)."""
        _core.commit(self.files, os.fspath(directory))
        return directory

    def __repr__(self):
        return f"Result({len(self.files)} files: {', '.join(list(self.files)[:6])}...)"


def _argument_error(function, key, detail, message=None):
    """An InputError of the Python layer's own checks, with the attributes the native ones
    carry: file (the function), line (None), key (the argument) and detail."""
    error = InputError(message or f"{function}: argument {key}: {detail}")
    error.file, error.line, error.key, error.detail = function, None, key, detail
    return error


def _thread_count(function, threads):
    """threads=: 0 for every core (the default), or a count >= 1."""
    if isinstance(threads, (bool, np.bool_)) or not isinstance(threads, numbers.Integral) or threads < 0:
        raise _argument_error(function, "threads", f"{threads!r}: 0 (every core) or a whole number of threads >= 1")
    return int(threads)


def _parameter_value(name, value):
    """A keyword argument's value as the native part takes it: a float, or an expression's text."""
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        detail = (f"a parameter takes a number or an expression in quotes (e.g. {name}=\"2*250\"), found "
                  f"{type(value).__name__}")
        raise _argument_error("keyword argument", name, detail, f"keyword argument {name}={value!r}: {detail}")
    return float(value)


class Problem:
    """A problem file's text, with parameters to override when it runs."""

    def __init__(self, text, file_name="<python>", overrides=None):
        self.text = text
        self.file_name = file_name
        self.overrides = dict(overrides or {})

    @classmethod
    def load(cls, path):
        path = os.fspath(path)
        with open(path, encoding="utf-8") as f:
            return cls(f.read(), path)

    @classmethod
    def from_dict(cls, data, name="<python>"):
        """A problem from Python values laid out as the file's tables (docs/problem-file.md)."""
        return cls(_toml.dumps(data), name)

    def data(self):
        """The file as a dictionary (tomllib)."""
        return tomllib.loads(self.text)

    @property
    def parameters(self):
        values = dict(self.data().get("parameters", {}))
        values.update(self.overrides)
        return values

    def with_parameters(self, **values):
        """A copy whose [parameters] of these names take these values: numbers, or
        expressions in quotes as the file writes them (P="2*250", R="L/4"), evaluated where
        the parameter stands in the file (they may use the parameters written before it)."""
        merged = dict(self.overrides)
        for name, value in values.items():
            merged[name] = _parameter_value(name, value)
        return Problem(self.text, self.file_name, merged)

    def sha256(self):
        return hashlib.sha256(self.text.encode()).hexdigest()

    def run(self, output=None, threads=0, gmsh_timeout=60.0, **parameters):
        """Solve; `parameters` override [parameters] by name (numbers or expressions in
        quotes, as with_parameters; or, for a .geo geometry, its DefineConstant numbers);
        `output` also writes the files there (the folder is replaced whole); `gmsh_timeout`:
        the seconds a .geo file may take to mesh (as --gmsh-timeout). Raises
        bemcontact.Error subclasses."""
        return self._go(False, output, threads, gmsh_timeout, parameters)

    def mesh(self, output=None, gmsh_timeout=60.0, **parameters):
        """Mesh only: the boundary mesh of every body and contact pairs."""
        return self._go(True, output, 0, gmsh_timeout, parameters)

    def _go(self, mesh_only, output, threads, gmsh_timeout, parameters):
        problem = self.with_parameters(**parameters) if parameters else self
        function = "mesh()" if mesh_only else "run()"
        try:
            timeout = float(gmsh_timeout)
        except (TypeError, ValueError):
            timeout = float("nan")
        if not (np.isfinite(timeout) and timeout > 0.0):
            raise _argument_error(function, "gmsh_timeout", f"{gmsh_timeout!r}: the seconds a .geo file may take to "
                                  f"mesh, a finite number > 0")
        raw = _core.run(problem.text, problem.file_name, problem.overrides, mesh_only,
                        _thread_count(function, threads), timeout)
        result = Result(raw)
        if output is not None:
            result.save(output)
        if result.solver_failure:
            error = SolverError(result.solver_failure + (f" (diagnostics in {output})" if output else ""))
            details = raw["solver_failure_details"]
            error.part = details["part"] or None
            error.iterations = details["iterations"] if details["iterations"] >= 0 else None
            error.residual = details["residual"] if details["residual"] >= 0 else None
            error.step = error.time = None
            raise error
        return result

    def __repr__(self):
        return f"Problem({self.file_name!r}, overrides={self.overrides})"


def run(path, output=None, threads=0, gmsh_timeout=60.0, **parameters):
    """Load a problem file and run it (Problem.load(path).run(...))."""
    return Problem.load(path).run(output=output, threads=threads, gmsh_timeout=gmsh_timeout, **parameters)
