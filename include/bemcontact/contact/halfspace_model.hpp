#pragma once
// An independent contact model of two elastic half-spaces in axisymmetry, the setting of
// Hertz's and Spence's theories (Annex E): a sphere of radius R (gap r^2 / 2R, Hertz's
// paraboloid) pressed by a force P on a flat, both bodies half-spaces. Its flexibility on
// the contact nodes comes from the Boussinesq-Cerruti ring kernels (kernels/halfspace_ring),
// not from the BEM, so that solving it with the same contact solver separates:
//  - the solver, the incremental Coulomb law and the measure of c, checked against Spence's
//    closed form (E.1) (validate spence-halfspace);
//  - the modelling of the thesis' ball (finite, curved bodies), which departs from the
//    half-space theory by O(a/R) (validate spence-sphere).
// Tractions are linear between the nodes (hat functions, as the BEM's linear elements), the
// displacements are collocated at the nodes. The pairs and the condensed problem follow the
// conventions of contact/condensed.hpp with the flat's normal: n = (0, -1) out of the
// sphere, t = (1, 0).
#include <vector>

#include "bemcontact/contact/condensed.hpp"

namespace bemcontact::contact {

// Surface flexibility of one half-space on hat functions over the radii (increasing, the
// first one may be 0): u = C q with u = (u_r, u_z) at each node and q = (q_r, q_z) the nodal
// traction values, 2N x 2N. upper: the half-space z > 0 (the sphere), else z < 0.
Matrix halfspace_surface_flexibility(const std::vector<double>& radii, const Material& material, bool upper);

struct HalfSpaceSphereContact {
  Material sphere, flat;
  double sphere_radius = 1.0;
  double force = 0.0;           // P > 0, pressing the bodies together
  std::vector<double> radii;    // contact nodes, increasing from 0
  bool tangential_coupling = true;
};

struct HalfSpaceModel {
  CondensedProblem condensed;
  std::vector<ContactPair> pairs;
};

// Throws bemcontact::Error for radii that do not start at 0 and increase, or P <= 0.
HalfSpaceModel halfspace_sphere_model(const HalfSpaceSphereContact& contact);

}  // namespace bemcontact::contact
