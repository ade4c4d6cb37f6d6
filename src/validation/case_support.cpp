#include "bemcontact/validation/case_support.hpp"

#include "bemcontact/core/error.hpp"

namespace bemcontact::validation {

io::ProblemFile load_example(const Context& context, const std::string& file) {
  return io::read_problem_file(context.examples_dir + "/" + file);
}

Index node_at(const geometry::BoundaryMesh& mesh, const Vec2& point) {
  const Index i = geometry::find_node_at(mesh, point, 1e-9 * mesh.scale);
  if (i < 0) throw Error("validation: no boundary node at the expected point");
  return i;
}

Index vertex_at(const geometry::BoundaryMesh& mesh, const Vec2& point) {
  const Index v = geometry::find_vertex_at(mesh, point, 1e-9 * mesh.scale);
  if (v < 0) throw Error("validation: no vertex at the expected point");
  return v;
}

Index interior_point_at(const bem::InteriorSolution& interior, const Vec2& point) {
  for (std::size_t k = 0; k < interior.points.size(); ++k)
    if ((interior.points[k] - point).norm() < 1e-9 * (1.0 + point.norm())) return static_cast<Index>(k);
  throw Error("validation: no interior point at the expected place");
}

std::vector<Record> skipped_on_compressed(const std::string& case_name) {
  std::vector<Record> records{report_value("skipped_dense_only", 1.0)};
  tag(records, 0, case_name, {});
  return records;
}

}  // namespace bemcontact::validation
