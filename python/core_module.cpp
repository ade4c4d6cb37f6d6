// The Python module's native part, bemcontact._core: the same driver as the command line
// (driver/run.hpp), files returned in memory with the tables of the CSV files as numpy
// arrays, errors raised as Python exceptions with the same messages. The Python package
// (python/bemcontact) builds the user-facing API on it.
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bemcontact/core/error.hpp"
#include "bemcontact/driver/probe.hpp"
#include "bemcontact/driver/run.hpp"
#include "bemcontact/io/input/expression.hpp"
#include "bemcontact/io/input/gmsh_geometry.hpp"
#include "bemcontact/io/output/output_directory.hpp"
#include "bemcontact/operators/dense_lu.hpp"
#include "bemcontact/io/text_format.hpp"

namespace py = pybind11;
using namespace bemcontact;

namespace {

// The values of a column of numbers as a read-only float64 array that owns them: the
// vector is moved into the array's base (a capsule), nothing is copied or formatted.
py::array_t<double> numpy_column(std::vector<double>&& numbers) {
  if (numbers.empty()) return py::array_t<double>(0);
  auto* owned = new std::vector<double>(std::move(numbers));
  py::capsule owner(owned, [](void* values) { delete static_cast<std::vector<double>*>(values); });
  py::array_t<double> array(static_cast<py::ssize_t>(owned->size()), owned->data(), owner);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// Each CSV file's table (io::CsvTable, moved out): file name -> [(column name, values)] in
// the file's column order, numbers as numpy arrays, text as lists of str.
py::dict as_tables(std::map<std::string, io::CsvTable>& tables) {
  py::dict result;
  for (auto& [name, table] : tables) {
    table.rows();  // (all columns of one length)
    py::list columns;
    for (auto& column : table.columns()) {
      py::object values = column.format == io::CsvTable::text ? py::object(py::cast(column.texts))
                                                             : py::object(numpy_column(std::move(column.numbers)));
      columns.append(py::make_tuple(column.name, values));
    }
    result[py::str(name)] = columns;
  }
  return result;
}

py::dict as_dict(driver::RunOutput& output) {
  py::dict files;  // insertion order = the order the driver wrote them
  for (const auto& file : output.files.files()) files[py::str(file.name)] = py::bytes(file.content);
  py::dict result;
  result["files"] = files;
  result["tables"] = as_tables(output.tables);
  result["report"] = output.report;
  result["warnings"] = output.warnings;
  result["solver_failure"] = output.solver_failure;
  const auto& failure = output.solver_failure_details;
  result["solver_failure_details"] =
      py::dict(py::arg("part") = failure.part, py::arg("iterations") = failure.iterations,
               py::arg("residual") = failure.residual);
  return result;
}

// The keyword arguments of run(): numbers, or expressions in the file's syntax (evaluated
// where the parameter stands in the file); messages name them as the caller wrote them.
io::ParameterOverrides keyword_overrides(const std::map<std::string, std::variant<double, std::string>>& values) {
  io::ParameterOverrides overrides;
  for (const auto& [name, value] : values) {
    io::ParameterValue replacing;
    if (const auto* text = std::get_if<std::string>(&value)) {
      replacing = io::ParameterValue(*text);
      replacing.origin = "keyword argument " + name + "='" + *text + "'";
    } else {
      replacing = io::ParameterValue(std::get<double>(value));
      replacing.origin = "keyword argument " + name + "=" + io::format_number(replacing.number);
    }
    overrides[name] = replacing;
  }
  return overrides;
}

// threads > 0: that many; 0: as many as the process had when the module was loaded (every
// core, or OMP_NUM_THREADS), so that one call's count does not stay for the next.
void use_threads(int threads) {
  static const int initial = omp_get_max_threads();
  omp_set_num_threads(threads > 0 ? threads : initial);
}

py::dict run(const std::string& text, const std::string& file_name,
             const std::map<std::string, std::variant<double, std::string>>& overrides, bool mesh_only, int threads,
             double gmsh_timeout) {
  driver::RunOptions options;
  options.keep_tables = true;
  options.overrides = keyword_overrides(overrides);
  options.limits.gmsh_timeout_seconds = gmsh_timeout;  // checked > 0 by the package
  driver::RunOutput output;
  {
    py::gil_scoped_release released;
    use_threads(threads);
    output = mesh_only ? driver::mesh_problem(text, file_name, options) : driver::run_problem(text, file_name, options);
  }
  return as_dict(output);
}

// `bemcontact probe` on a result's files in memory: points (their position in the list
// stands for the line of a points file in messages) and lines (x0, y0, x1, y1, n).
py::dict probe(const std::map<std::string, py::bytes>& files, const std::vector<std::array<double, 2>>& points,
               const std::vector<std::tuple<double, double, double, double, int>>& lines, int threads,
               std::int64_t max_points) {
  std::map<std::string, std::string> contents;
  for (const auto& [name, content] : files) contents[name] = std::string(content);
  driver::ProbeRequest request;
  request.points_file = "<points>";
  for (std::size_t k = 0; k < points.size(); ++k)
    request.listed.push_back({Vec2(points[k][0], points[k][1]), static_cast<int>(k) + 1});
  for (const auto& [x0, y0, x1, y1, n] : lines) request.lines.push_back({Vec2(x0, y0), Vec2(x1, y1), n});
  driver::ProbeOptions options;
  options.run_name = "the result";
  options.keep_tables = true;
  options.request_source = "probe()";
  options.points_hint = "points=[(x, y), ...] or lines=[(x0, y0, x1, y1, n), ...]";
  options.limit_hint = "raise it with max_points=";
  options.limits.max_interior_points = max_points;
  driver::ProbeOutput output;
  {
    py::gil_scoped_release released;
    use_threads(threads);
    output = driver::probe_run(
        [&](const std::string& name) -> std::optional<std::string> {
          const auto found = contents.find(name);
          if (found == contents.end()) return std::nullopt;
          return found->second;
        },
        request, options);
  }
  py::dict probe_files;
  for (const auto& file : output.files.files()) probe_files[py::str(file.name)] = py::bytes(file.content);
  py::dict result;
  result["files"] = probe_files;
  result["tables"] = as_tables(output.tables);
  result["report"] = output.report;
  result["warnings"] = output.warnings;
  return result;
}

void commit(const std::map<std::string, py::bytes>& files, const std::string& directory) {
  io::OutputDirectory output;
  for (const auto& [name, content] : files) output.add(name, std::string(content));
  py::gil_scoped_release released;
  output.commit(directory);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "bemcontact's native part; use the bemcontact package instead";
  operators::use_single_threaded_blas();
  use_threads(0);  // the count the process starts with, kept for threads=0
  // The error classes, and a translator that gives each raised error its data as attributes:
  // InputError.file/.line/.key/.detail, GeometryError.places/.detail (file, line, key per
  // boundary), SolverError.part/.iterations/.residual/.step/.time (None where unknown).
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<InputError> input_error(m, "InputError", error.ptr());
  static py::exception<GeometryError> geometry_error(m, "GeometryError", error.ptr());
  static py::exception<SolverError> solver_error(m, "SolverError", error.ptr());
  py::register_exception_translator([](std::exception_ptr raised) {
    const auto raise = [](const py::object& type, const std::string& message, const py::dict& attributes) {
      py::object instance = type(message);
      for (const auto& [name, value] : attributes) instance.attr(name) = value;
      PyErr_SetObject(type.ptr(), instance.ptr());
    };
    const auto place = [](const SourceLocation& where) {
      return py::make_tuple(where.file, where.line > 0 ? py::object(py::int_(where.line)) : py::object(py::none()),
                            where.key.empty() ? py::object(py::none()) : py::object(py::str(where.key)));
    };
    const auto known = [](auto value, auto unknown) { return value == unknown ? py::object(py::none()) : py::cast(value); };
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const InputError& e) {
      const auto [file, line, key] = place(e.where()).cast<std::tuple<py::object, py::object, py::object>>();
      raise(input_error, e.what(), py::dict(py::arg("file") = file, py::arg("line") = line, py::arg("key") = key,
                                            py::arg("detail") = e.detail()));
    } catch (const GeometryError& e) {
      py::list places;
      for (const auto& where : e.where()) places.append(place(where));
      raise(geometry_error, e.what(), py::dict(py::arg("places") = places, py::arg("detail") = e.detail()));
    } catch (const SolverError& e) {
      const auto& f = e.failure();
      raise(solver_error, e.what(),
            py::dict(py::arg("part") = f.part.empty() ? py::object(py::none()) : py::object(py::str(f.part)),
                     py::arg("iterations") = known(f.iterations, -1), py::arg("residual") = known(f.residual, -1.0),
                     py::arg("step") = known(f.step, -1), py::arg("time") = known(f.time, -1.0)));
    } catch (const Error& e) {
      raise(error, e.what(), py::dict());
    }
  });
  m.attr("__version__") = BEMCONTACT_VERSION;
  m.attr("reads_geo_files") = io::gmsh_api_available();  // .geo through the Gmsh library
  m.def("run", &run, py::arg("text"), py::arg("file_name"), py::arg("overrides"), py::arg("mesh_only") = false,
        py::arg("threads") = 0, py::arg("gmsh_timeout") = 60.0,
        "Solve (or only mesh) a problem text; returns files, tables (the CSV files' columns), report, warnings. gmsh_timeout: the seconds a .geo "
        "file may take to mesh (as --gmsh-timeout).");
  m.def("probe", &probe, py::arg("files"), py::arg("points"), py::arg("lines"), py::arg("threads") = 0,
        py::arg("max_points") = 2000000,
        "Values at new points of a result (as `bemcontact probe`); returns files, tables, report, warnings.");
  m.def("commit", &commit, py::arg("files"), py::arg("directory"),
        "Replace `directory` whole by these files (as `bemcontact run -o`).");
}
