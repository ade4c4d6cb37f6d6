#include "bemcontact/dd/plate_strips.hpp"

#include <cmath>
#include <string>

namespace bemcontact::dd {

namespace {

geometry::BoundaryPiece line(const std::string& name, Vec2 from, Vec2 to, int elements) {
  geometry::BoundaryPiece piece = geometry::line_piece(name, from, to, elements);
  piece.where.key = name;
  return piece;
}

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace

DecompositionProblem plate_strips(const PlateStripsSpec& spec) {
  DecompositionProblem problem;
  problem.title = "plate in tension, " + std::to_string(spec.strips) + " strips, h = 1/" +
                  std::to_string(spec.elements_per_unit);
  problem.source_file = "plate_strips";
  problem.analysis = spec.analysis;
  problem.options.set_method(spec.method);
  const int n = spec.strips;
  const double T = spec.height / n;
  const int across = 2 * spec.elements_per_unit;
  const int up = std::max(1, static_cast<int>(std::lround(T * spec.elements_per_unit)));
  const double P = spec.applied_stress;
  for (int s = 0; s < n; ++s) {
    const double y0 = s * T, y1 = (s + 1) * T;
    Subdomain sub;
    sub.body.name = "strip" + std::to_string(s + 1);
    sub.body.material = spec.material;
    sub.body.pieces = {line("bottom", {-1.0, y0}, {1.0, y0}, across), line("right", {1.0, y0}, {1.0, y1}, up),
                       line("top", {1.0, y1}, {-1.0, y1}, across), line("left", {-1.0, y1}, {-1.0, y0}, up)};
    sub.body.conditions.assign(4, bem::BoundaryCondition{});
    sub.piece_interface.assign(4, "");
    if (s == 0) {  // u2 = 0, p1 = 0
      auto& c = sub.body.conditions[0];
      c.kind = {bem::ConditionKind::traction, bem::ConditionKind::displacement};
      c.signature = "global:t1=0;u2=0";
      bem::PointConstraint origin;
      origin.position = Vec2(0.0, 0.0);
      origin.displacement[0] = 0.0;
      origin.label = "O";
      sub.body.constraints.push_back(origin);
    } else {
      mark_interface(sub, 0, "y" + std::to_string(s));
    }
    if (s == n - 1) {  // p2 = P
      auto& c = sub.body.conditions[2];
      c.value[1] = [P](const Vec2&) { return P; };
      c.signature = "global:t1=0;t2=" + number(P);
    } else {
      mark_interface(sub, 2, "y" + std::to_string(s + 1));
    }
    for (std::size_t p = 0; p < 4; ++p) sub.body.pieces[p].condition_signature = sub.body.conditions[p].signature;
    problem.subdomains.push_back(std::move(sub));
  }
  return problem;
}

}  // namespace bemcontact::dd
