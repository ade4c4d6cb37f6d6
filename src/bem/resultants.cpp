#include "bemcontact/bem/resultants.hpp"

#include <numbers>

#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::bem {

std::vector<BoundaryResultant> boundary_resultants(const geometry::BoundaryMesh& mesh,
                                                   const BoundarySolution& solution,
                                                   const BodyDefinition& body, AnalysisType type) {
  std::vector<BoundaryResultant> out;
  auto entry = [&](const std::string& name) -> BoundaryResultant& {
    for (auto& r : out)
      if (r.boundary == name) return r;
    BoundaryResultant r;
    r.boundary = name;
    for (std::size_t p = 0; p < body.pieces.size(); ++p)
      if (body.pieces[p].name == name)
        for (const auto kind : body.conditions.at(p).kind)
          r.prescribed_displacement = r.prescribed_displacement || kind == ConditionKind::displacement;
    out.push_back(r);
    return out.back();
  };
  // 5 points: exact for quadratic tractions times the linear r of axisymmetry on lines.
  const quadrature::Rule& rule = quadrature::gauss_legendre(5);
  const bool axisymmetric = type == AnalysisType::axisymmetric;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const auto& element = mesh.elements[e];
    BoundaryResultant& r = entry(mesh.piece_names.at(element.piece));
    for (int i = 0; i < rule.size(); ++i) {
      const double f = 0.5 * (1.0 + rule.nodes[i]);
      const Vec2 y = element.point(f);
      double w = 0.5 * rule.weights[i] * element.jacobian();
      if (axisymmetric) w *= 2.0 * std::numbers::pi * y.x();
      Vec2 t = Vec2::Zero();
      for (int a = 0; a < element.node_count; ++a) t += element.shape(a, f) * solution.traction[element.nodes[a]];
      r.force += w * t;
      if (!axisymmetric) r.moment += w * (y.x() * t.y() - y.y() * t.x());
    }
  }
  if (axisymmetric)
    for (auto& r : out) r.force.x() = 0.0;
  return out;
}

}  // namespace bemcontact::bem
