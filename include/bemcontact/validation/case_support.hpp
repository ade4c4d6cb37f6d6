#pragma once
// Helpers shared by the reference cases: reading a bundled example, finding a mesh node,
// vertex or interior point that a case reports on.
#include <string>

#include "bemcontact/bem/solution.hpp"
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/io/problem_file.hpp"
#include "bemcontact/validation/validation.hpp"

namespace bemcontact::validation {

io::ProblemFile load_example(const Context& context, const std::string& file);
// Throw when the mesh has no node / vertex there (a changed example must fail loudly).
Index node_at(const geometry::BoundaryMesh& mesh, const Vec2& point);
Index vertex_at(const geometry::BoundaryMesh& mesh, const Vec2& point);
Index interior_point_at(const bem::InteriorSolution& interior, const Vec2& point);

}  // namespace bemcontact::validation
