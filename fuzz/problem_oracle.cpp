#include "problem_oracle.hpp"

#include <cctype>
#include <cstring>
#include <exception>
#include <new>

#include "bemcontact/core/error.hpp"
#include "bemcontact/driver/run.hpp"
#include "bemcontact/io/input/gmsh_geometry.hpp"

namespace bemcontact::fuzz {

namespace {

// "fuzz.toml:<line>: ..." with line >= 1.
bool names_file_and_line(const std::string& message) {
  const std::string prefix = std::string(input_name) + ":";
  if (message.rfind(prefix, 0) != 0) return false;
  std::size_t i = prefix.size();
  const std::size_t digits = i;
  while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) ++i;
  return i > digits && message.compare(digits, 1, "0") != 0;
}

std::string check_input_error(const std::string& message) {
  if (!names_file_and_line(message)) return "input error without file and line: " + message;
  if (message.find("key '") == std::string::npos && message.find("TOML syntax error") == std::string::npos)
    return "input error without key: " + message;
  return {};
}

std::string check_geometry_error(const std::string& message) {
  // A boundary or vertex name in quotes, or a point "(x, y)".
  if (message.find('\'') == std::string::npos && message.find('(') == std::string::npos)
    return "geometry error naming no boundary, vertex or point: " + message;
  return {};
}

}  // namespace

std::string check_problem_text(std::string_view text) {
  driver::RunOptions options;
  // Small limits keep every run short; the checks that enforce them are part of the test.
  options.limits.max_elements = 1500;
  options.limits.max_interior_points = 5000;
  options.limits.max_memory_bytes = 400e6;
  try {
    if (driver::problem_kind(text) == driver::ProblemKind::body) driver::mesh_problem(text, input_name, options);
    driver::run_problem(text, input_name, options);
  } catch (const InputError& e) {
    return check_input_error(e.what());
  } catch (const GeometryError& e) {
    return check_geometry_error(e.what());
  } catch (const SolverError& e) {
    if (std::strlen(e.what()) == 0) return "solver error without a message";
    return {};
  } catch (const std::bad_alloc&) {
    return "std::bad_alloc (a resource limit is missing)";
  } catch (const Error& e) {
    return std::string("unclassified bemcontact::Error: ") + e.what();
  } catch (const std::exception& e) {
    return std::string("unexpected exception: ") + e.what();
  }
  return {};
}

std::string check_gmsh_file(const std::filesystem::path& file) {
  io::GmshOptions options;
  options.limits.max_elements = 1500;
  options.limits.max_memory_bytes = 400e6;
  options.limits.gmsh_timeout_seconds = 0.5;
  try {
    (void)io::read_gmsh_boundary(file, false, options);
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.rfind(file.string() + ":", 0) != 0) return "input error without the file: " + message;
    if (file.extension() == ".msh" && e.where().line <= 0) return "input error without the line: " + message;
    return {};
  } catch (const std::bad_alloc&) {
    return "std::bad_alloc (a resource limit is missing)";
  } catch (const std::exception& e) {
    return std::string("unexpected exception: ") + e.what();
  }
  return {};
}

}  // namespace bemcontact::fuzz
