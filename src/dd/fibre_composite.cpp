#include "bemcontact/dd/fibre_composite.hpp"

#include <string>

#include "bemcontact/core/error.hpp"

namespace bemcontact::dd {

namespace {

geometry::BoundaryPiece named(geometry::BoundaryPiece piece, const std::string& name) {
  piece.name = name;
  piece.where.key = name;
  return piece;
}

geometry::BoundaryPiece arc(const std::string& name, const Vec2& from, const Vec2& to, const Vec2& centre,
                            bool counterclockwise, int elements) {
  geometry::BoundaryPiece piece = geometry::line_piece(name, from, to, elements);
  piece.shape = geometry::PieceShape::arc;
  piece.center = centre;
  piece.counterclockwise = counterclockwise;
  return named(piece, name);
}

}  // namespace

Vec2 fibre_centre(const FibreCompositeSpec& spec, int k) {
  const int n = spec.fibres_per_side;
  const double first = -0.5 * (n - 1) * spec.pitch;
  return {first + (k % n) * spec.pitch, first + (k / n) * spec.pitch};
}

DecompositionProblem fibre_composite(const FibreCompositeSpec& spec) {
  const int n = spec.fibres_per_side;
  const double R = spec.fibre_radius, W = spec.half_width;
  if (n < 1 || spec.pitch <= 2.0 * R || 0.5 * (n - 1) * spec.pitch + R >= W)
    throw Error("fibre_composite: the fibres must lie apart and inside the matrix");
  DecompositionProblem problem;
  problem.title = "fibre composite, " + std::to_string(n * n) + " fibres";
  problem.source_file = "fibre_composite";
  problem.analysis = spec.analysis;
  problem.options.set_method(spec.method);

  Subdomain matrix;
  matrix.body.name = "matrix";
  matrix.body.material = spec.matrix;
  const Vec2 corners[4] = {{-W, -W}, {W, -W}, {W, W}, {-W, W}};
  const char* sides[4] = {"bottom", "right", "top", "left"};
  const double sigma = spec.applied_stress;
  for (int s = 0; s < 4; ++s) {
    matrix.body.pieces.push_back(named(geometry::line_piece(sides[s], corners[s], corners[(s + 1) % 4], spec.elements_per_side), sides[s]));
    bem::BoundaryCondition condition;
    if (s == 1 || s == 3) {  // x = +-W: t1 = sigma n1
      const double t1 = s == 1 ? sigma : -sigma;
      condition.value[0] = [t1](const Vec2&) { return t1; };
      condition.signature = std::string("global:t1=") + (s == 1 ? "+" : "-") + "sigma";
    } else {
      condition.signature = "global:free";
    }
    matrix.body.conditions.push_back(condition);
    matrix.piece_interface.push_back("");
  }
  for (int k = 0; k < n * n; ++k) {
    const Vec2 c = fibre_centre(spec, k);
    const Vec2 quarter[4] = {c + Vec2(R, 0), c + Vec2(0, R), c + Vec2(-R, 0), c + Vec2(0, -R)};
    Subdomain fibre;
    fibre.body.name = "fibre" + std::to_string(k + 1);
    fibre.body.material = spec.fibre;
    for (int q = 0; q < 4; ++q) {
      const std::string name = "fibre" + std::to_string(k + 1) + "_q" + std::to_string(q + 1);
      fibre.body.pieces.push_back(arc(name, quarter[q], quarter[(q + 1) % 4], c, true, spec.elements_per_quarter));
      mark_interface(fibre, static_cast<std::size_t>(q), name);
    }
    fibre.interior_points.push_back({c, false, {}, {-1, -1}});
    // The hole in the matrix runs clockwise: the same quarters, reversed.
    for (int q = 3; q >= 0; --q) {
      const std::string name = "fibre" + std::to_string(k + 1) + "_q" + std::to_string(q + 1);
      matrix.body.pieces.push_back(arc(name, quarter[(q + 1) % 4], quarter[q], c, false, spec.elements_per_quarter));
      mark_interface(matrix, matrix.body.pieces.size() - 1, name);
    }
    problem.subdomains.push_back(std::move(fibre));
  }
  for (const auto& [position, components] : {std::pair{Vec2(-W, 0.0), 2}, std::pair{Vec2(W, 0.0), 1}}) {
    bem::PointConstraint constraint;
    constraint.position = position;
    constraint.displacement[1] = 0.0;
    if (components == 2) constraint.displacement[0] = 0.0;
    constraint.label = components == 2 ? "left middle" : "right middle";
    matrix.body.constraints.push_back(constraint);
  }
  for (std::size_t p = 0; p < 4; ++p) matrix.body.pieces[p].condition_signature = matrix.body.conditions[p].signature;
  problem.subdomains.insert(problem.subdomains.begin(), std::move(matrix));
  return problem;
}

}  // namespace bemcontact::dd
