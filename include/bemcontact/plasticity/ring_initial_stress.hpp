#pragma once
// The field of an initial stress sigma0 constant on each cell of an axisymmetric body's
// meridian section: the axisymmetric domain term of the initial-strain formulation
// (plasticity/initial_stress.hpp for the plane one), with the ring kernels of
// kernels/axisymmetric.hpp (per radian, weight r).
//
// For a body of revolution the cell is a ring, and its constant cylindrical components
// (rr, zz, rz, tt) of sigma0 do not have zero divergence:
//   div sigma0 = ((s_rr - s_tt) / r) e_r + (s_rz / r) e_z
// (the hoop stress pulls the ring inward). The divergence theorem on the ring then leaves,
// besides the edge integrals of sigma0 n, an area integral of that body force, whose 1/r
// cancels the ring's weight r:
//   u(x) += sum_cells [ int_edges U(x, y) sigma0 n r dGamma
//                       - int_cell ( U(x, y)_{.r} (s_rr - s_tt) + U(x, y)_{.z} s_rz ) dr dz ]
// and C eps(x) likewise with D (the stress at x of a ring load at y), sigma = C eps - sigma0
// inside the cell. The area integrand is singular at x only (log for U, 1/rho for D): it is
// integrated on the triangles from x to each edge with Duffy's map (s dr dz), exactly
// where x is near the cell, and on the cell's own triangles away from it.
#include "bemcontact/kernels/axisymmetric.hpp"
#include "bemcontact/plasticity/initial_stress.hpp"

namespace bemcontact::plasticity {

using Matrix24 = Eigen::Matrix<double, 2, 4>;
using Matrix44 = Eigen::Matrix4d;

// The displacement (r, z) at x per unit initial stress component of the cell (columns rr,
// zz, rz, tt). x may lie on an edge (a collocation node).
Matrix24 ring_cell_displacement_influence(const kernels::KelvinAxisymmetric& kernel, const Vec2& x, const Cell& cell);

// C eps at x (rows rr, zz, rz, tt) per unit initial stress component of the cell; x must not
// lie on the cell's edges.
Matrix44 ring_cell_stress_influence(const kernels::KelvinAxisymmetric& kernel, const Vec2& x, const Cell& cell);

}  // namespace bemcontact::plasticity
