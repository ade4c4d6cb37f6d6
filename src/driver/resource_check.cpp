#include "bemcontact/driver/resource_check.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string_view>

#include "bemcontact/core/error.hpp"

namespace bemcontact::driver {

namespace {

// Nodes of a body: one per element end (linear) or element (constant), plus the split
// corners, at most one per piece.
std::int64_t body_unknowns(const bem::BodyDefinition& body) {
  std::int64_t nodes = 0;
  for (const auto& piece : body.pieces) nodes += static_cast<std::int64_t>(piece.elements) + 1;
  return 2 * nodes;
}

std::int64_t body_elements(const bem::BodyDefinition& body) {
  std::int64_t elements = 0;
  for (const auto& piece : body.pieces) elements += piece.elements;
  return elements;
}

// H and G assembled, the system matrix and its LU factors: four dense n x n matrices at
// the peak of a one-body solve.
double dense_body_bytes(std::int64_t unknowns) {
  const double n = static_cast<double>(unknowns);
  return 4.0 * 8.0 * n * n;
}

void check_body(const bem::BodyDefinition& body, const std::string& what, const ResourceLimits& limits,
                const std::string& file) {
  const std::int64_t elements = body_elements(body);
  if (elements > limits.max_elements)
    throw InputError(SourceLocation{file, body.pieces.empty() ? 0 : body.pieces.front().where.line,
                                    body.pieces.empty() ? "" : body.pieces.front().where.key},
                     what + " has " + std::to_string(elements) + " elements in all, over the limit of " +
                         std::to_string(limits.max_elements) +
                         " (raise it with --max-elements if the machine has the memory)");
}

void check_memory(const ResourceEstimate& estimate, const ResourceLimits& limits, const std::string& file) {
  const double limit = limits.memory_limit_bytes();
  if (estimate.bytes > limit)
    throw InputError(SourceLocation{file, 0, ""},
                     "the dense boundary systems of this problem (" + std::to_string(estimate.unknowns) +
                         " unknowns in the largest body) need about " + format_bytes(estimate.bytes) +
                         " of memory, over the limit of " + format_bytes(limit) +
                         "; use fewer elements, or raise the limit with --max-memory (GB) on a larger machine");
}

void check_points(std::size_t points, const ResourceLimits& limits, const std::string& file) {
  if (static_cast<std::int64_t>(points) > limits.max_interior_points)
    throw InputError(SourceLocation{file, 0, "interior"},
                     std::to_string(points) + " interior points, over the limit of " +
                         std::to_string(limits.max_interior_points) + " (raise it with --max-points)");
}

}  // namespace

ResourceEstimate estimate_resources(const bem::ProblemDefinition& problem) {
  ResourceEstimate estimate;
  estimate.unknowns = body_unknowns(problem.body);
  estimate.bytes = dense_body_bytes(estimate.unknowns);
  return estimate;
}

ResourceEstimate estimate_resources(const dd::DecompositionProblem& problem) {
  // Every subdomain stays factored while the interface problem is solved.
  ResourceEstimate estimate;
  double factored = 0.0, largest = 0.0;
  for (const auto& subdomain : problem.subdomains) {
    const std::int64_t n = body_unknowns(subdomain.body);
    estimate.unknowns = std::max(estimate.unknowns, n);
    factored += 2.0 * 8.0 * static_cast<double>(n) * static_cast<double>(n);
    largest = std::max(largest, dense_body_bytes(n));
  }
  estimate.bytes = factored + largest;
  return estimate;
}

ResourceEstimate estimate_resources(const contact::ContactProblem& problem) {
  ResourceEstimate estimate;
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions) {
      const std::int64_t n = body_unknowns(region.body);
      estimate.unknowns = std::max(estimate.unknowns, n);
      estimate.bytes += dense_body_bytes(n);
    }
  return estimate;
}

void check_resources(const bem::ProblemDefinition& problem, const ResourceLimits& limits) {
  check_body(problem.body, "the body", limits, problem.source_file);
  check_points(problem.interior_points.size(), limits, problem.source_file);
  check_memory(estimate_resources(problem), limits, problem.source_file);
}

void check_resources(const dd::DecompositionProblem& problem, const ResourceLimits& limits) {
  std::size_t points = 0;
  for (const auto& subdomain : problem.subdomains) {
    check_body(subdomain.body, "subdomain '" + subdomain.body.name + "'", limits, problem.source_file);
    points += subdomain.interior_points.size();
  }
  check_points(points, limits, problem.source_file);
  check_memory(estimate_resources(problem), limits, problem.source_file);
}

void check_resources(const contact::ContactProblem& problem, const ResourceLimits& limits) {
  std::size_t points = 0;
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions) {
      check_body(region.body, "region '" + region.body.name + "' of body '" + body.name + "'", limits, problem.source_file);
      points += region.interior_points.size();
    }
  check_points(points, limits, problem.source_file);
  check_memory(estimate_resources(problem), limits, problem.source_file);
}

namespace {

bool is_non_finite_token(std::string_view token) {
  if (!token.empty() && (token.front() == '-' || token.front() == '+')) token.remove_prefix(1);
  if (token.size() != 3 && token.size() != 8) return false;
  std::string lower;
  for (const char c : token) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

[[noreturn]] void report_non_finite(const std::string& file, std::size_t line, std::size_t column,
                                    std::string_view token) {
  throw SolverError("the results hold a non-finite value (" + std::string(token) + ") in " + file + ", line " +
                    std::to_string(line) + ", field " + std::to_string(column) +
                    ": the solution broke down (check the data for extreme values); nothing was written");
}

// CSV (RFC 4180: a quoted field is text) and legacy VTK (the first two lines are the
// header and the title; the rest is whitespace-separated).
void check_text_file(const io::OutputDirectory::File& file, bool csv) {
  const std::string& text = file.content;
  std::size_t line = 1, field = 1, start = 0;
  bool quoted = false, in_quotes = false;
  const auto close_field = [&](std::size_t end) {
    if (!quoted && (csv || line > 2)) {
      const std::string_view token(text.data() + start, end - start);
      if (is_non_finite_token(token)) report_non_finite(file.name, line, field, token);
    }
  };
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const char c = i < text.size() ? text[i] : '\n';
    if (in_quotes) {
      if (c == '"') in_quotes = false;
      continue;
    }
    if (c == '"' && i == start) {
      quoted = in_quotes = true;
      continue;
    }
    const bool separator = csv ? c == ',' : (c == ' ' || c == '\t');
    if (separator || c == '\n' || c == '\r') {
      close_field(i);
      start = i + 1;
      quoted = false;
      ++field;
      if (c == '\n') ++line, field = 1;
    }
  }
}

}  // namespace

void check_output_finite(const io::OutputDirectory& files) {
  for (const auto& file : files.files()) {
    const std::string& name = file.name;
    const auto ends_with = [&](std::string_view suffix) {
      return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (ends_with(".csv")) check_text_file(file, true);
    else if (ends_with(".vtk")) check_text_file(file, false);
  }
}

}  // namespace bemcontact::driver
