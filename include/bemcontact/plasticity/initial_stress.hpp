#pragma once
// The field of an initial stress sigma0 that is constant on each polygonal cell (plane
// strain; plane stress with the kernel's nu): the domain term of the initial-strain boundary
// element formulation of elastoplasticity [BrebbiaTellesWrobel1984, ch. 13; BonnetMukherjee1996],
// written as line integrals over the cells' edges.
//
// With sigma = C eps - sigma0 and div sigma = 0, Somigliana's identity gains
//   int_Omega grad_y U(x, y) : sigma0(y) dOmega = sum_e int_{dE} U(x, y) sigma0_e n_e dGamma
// (the divergence theorem on each cell, where sigma0 is constant and U weakly singular), so
//   c u(x) + int T u = int U t + sum_e int_{dE} U sigma0_e n_e                (boundary equation)
//   C eps(x) = int D t - int S u + sum_e int_{dE} D sigma0_e n_e,  sigma = C eps - sigma0
// at a point x off every edge (t the true traction). The strongly singular domain kernel
// and its free term never appear: a cell's own edges are at a distance from its interior
// points. The edge integrals are graded toward the point of the edge nearest to x (the
// logarithm of U on an edge through x, the 1/r of D near one).
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "bemcontact/kernels/kelvin2d.hpp"

namespace bemcontact::plasticity {

// A polygonal cell: a simple polygon, its vertices counterclockwise, no vertex where the
// boundary runs straight on (convex or not: its field is the integral over its edges).
struct Cell {
  std::vector<Vec2> vertices;
  Vec2 centroid() const;  // of the area
  double area() const;
  bool convex() const;
  // Triangles that tile the cell: the fan from vertex 0 when convex, else ear
  // clipping (empty when no ear is found: not a simple polygon).
  std::vector<std::array<Vec2, 3>> triangles() const;
  bool contains(const Vec2& point) const;  // strictly inside (the even-odd rule)
  // The lower-left and upper-right corners of an axis-aligned rectangle (a quadtree
  // leaf, whichever vertex comes first), none for any other cell.
  std::optional<std::array<Vec2, 2>> rectangle() const;
  // Points strictly inside the cell and weights summing to 1 for its mean of a field: the
  // n x n Gauss points of an axis-aligned rectangle (n = 2 refinement), else each triangle
  // of triangles() split into refinement^2 similar ones with three points each (degree 2:
  // the barycentric 2/3, 1/6, 1/6 points).
  std::vector<std::pair<Vec2, double>> mean_points(int refinement = 1) const;
};

// In-plane initial stress components (11, 22, 12).
using InitialStress = Eigen::Vector3d;
using Matrix23 = Eigen::Matrix<double, 2, 3>;
using Matrix33 = Eigen::Matrix3d;

// The in-plane C on the tensor components (11, 22, 12): plane strain (eps_33 = 0) or plane
// stress (sigma_33 = 0, the reduced stiffness); C eps of an in-plane strain.
Matrix33 in_plane_stiffness(AnalysisType type, const Material& material);

// The displacement at x (2 components) per unit initial stress component of the cell
// (columns 11, 22, 12). x may lie on an edge (a collocation node of the boundary).
Matrix23 cell_displacement_influence(const kernels::KelvinPlane& kernel, const Vec2& x, const Cell& cell);

// C eps at x (rows 11, 22, 12) per unit initial stress component of the cell; x must not
// lie on the cell's edges (inside the cell is allowed: then sigma = C eps - sigma0 there).
Matrix33 cell_stress_influence(const kernels::KelvinPlane& kernel, const Vec2& x, const Cell& cell);

}  // namespace bemcontact::plasticity
