#pragma once
// Helpers shared by the reference cases: reading a bundled example, finding a mesh node,
// vertex or interior point that a case reports on.
#include <string>

#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/solution.hpp"
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/validation/validation.hpp"

namespace bemcontact::validation {

io::ProblemFile load_example(const Context& context, const std::string& file);
// Throw when the mesh has no node / vertex there (a changed example must fail loudly).
Index node_at(const geometry::BoundaryMesh& mesh, const Vec2& point);
Index vertex_at(const geometry::BoundaryMesh& mesh, const Vec2& point);
Index interior_point_at(const bem::InteriorSolution& interior, const Vec2& point);
// The one record of a case that runs on dense operators only (an elastoplastic region),
// under --operator compressed: it would repeat itself.
std::vector<Record> skipped_on_compressed(const std::string& case_name);

// Runs a case with linear and with quadratic elements: measure(problem, records) appends
// the records of one variant and returns its element count; each variant's records are
// tagged with its interpolation and element count.
template <class Measure>
std::vector<Record> for_each_interpolation(const std::string& case_name, const bem::ProblemDefinition& base,
                                           Measure measure) {
  std::vector<Record> records;
  for (Interpolation interpolation : {Interpolation::linear, Interpolation::quadratic}) {
    bem::ProblemDefinition problem = base;
    problem.mesh.interpolation = interpolation;
    const std::size_t first = records.size();
    const Index elements = measure(static_cast<const bem::ProblemDefinition&>(problem), records);
    tag(records, first, case_name, {{"interpolation", to_string(interpolation)}, {"elements", std::to_string(elements)}});
  }
  return records;
}

}  // namespace bemcontact::validation
