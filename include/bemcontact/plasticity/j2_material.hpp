#pragma once
// Small-strain J2 (von Mises) plasticity with linear isotropic and linear kinematic
// (Prager-Ziegler) hardening: the material point of an elastoplastic region (issue 30).
// Elastic-perfectly plastic is the case of zero hardening.
//
//   sigma = K tr(eps) 1 + 2 G dev(eps - eps_p)
//   xi = dev(sigma) - alpha,   f = |xi| - sqrt(2/3) (Y + H_iso kappa) <= 0
//   eps_p' = gamma' n,  alpha' = (2/3) H_kin gamma' n,  kappa' = sqrt(2/3) gamma',  n = xi/|xi|
// (|.| the Frobenius norm; kappa is the equivalent plastic strain, so that in uniaxial
// tension the yield stress grows by H_iso kappa and the back stress by H_kin eps_p: the
// tangent modulus is E H / (E + H), H = H_iso + H_kin) [SimoHughes1998, Box 3.2].
//
// The update is the radial return (backward Euler, exact for linear hardening) with its
// consistent tangent [SimoTaylor1985]:
//   C = K 1 (x) 1 + 2 G theta (I - 1/3 1 (x) 1) - 2 G theta_bar n (x) n,
//   theta = 1 - 2 G dgamma / |xi_trial|,  theta_bar = 1 / (1 + (H_iso + H_kin) / 3G) - (1 - theta).
// Plane strain and axisymmetry give the whole strain (eps_33 = 0, or u_r / r); plane stress
// finds eps_33 with sigma_33 = 0 by Newton on the same update, its tangent condensed.
//
// Symmetric tensors are Mandel vectors (11, 22, 33, sqrt2 12): the double contraction is the
// dot product and the tangent is a symmetric 4 x 4 matrix.
#include <Eigen/Core>

#include "bemcontact/core/types.hpp"

namespace bemcontact::plasticity {

using Mandel = Eigen::Vector4d;
using MandelMatrix = Eigen::Matrix4d;

// Mandel vector of the symmetric tensor with components (11, 22, 33, 12), and back.
Mandel mandel(double s11, double s22, double s33, double s12);
double component12(const Mandel& v);  // the tensor component 12 of a Mandel vector

struct J2Hardening {
  double yield_stress = 0.0;  // Y > 0: initial yield stress in uniaxial tension
  double isotropic = 0.0;     // H_iso >= 0: growth of the yield stress per unit kappa
  double kinematic = 0.0;     // H_kin >= 0: growth of the back stress (uniaxial: per unit eps_p)
};

// The history of a material point.
struct J2State {
  Mandel plastic_strain = Mandel::Zero();
  Mandel back_stress = Mandel::Zero();
  double equivalent_plastic_strain = 0.0;  // kappa
};

struct J2Update {
  Mandel stress = Mandel::Zero();
  Mandel strain = Mandel::Zero();  // the total strain (plane stress: with the eps_33 found)
  J2State state;
  MandelMatrix tangent = MandelMatrix::Zero();  // d stress / d strain, consistent with the update
  bool plastic = false;
  double yield_function_trial = 0.0;  // f of the elastic trial (> 0: the step yields)
  double plastic_increment = 0.0;     // the step's increment of kappa (< 0 only when held on the surface)
};

// The elastic stiffness on Mandel vectors.
MandelMatrix elastic_stiffness(const Material& material);

// A point held in one state whatever its trial: on the yield surface (returned to it even
// from inside, a negative plastic increment) or elastic (no return even from outside). The
// stabilisation of a structural Newton whose points cycle between elastic and plastic
// (elastoplastic_region.hpp: held, then released to the state the solution asks), never the
// material law itself.
enum class J2Hold { none, on_surface, elastic };

// The stress of the total strain `strain` from the state `previous` (plane strain,
// axisymmetry, 3D: every component given).
J2Update j2_update(const Material& material, const J2Hardening& hardening, const J2State& previous,
                   const Mandel& strain, J2Hold hold = J2Hold::none);

// Plane stress: the in-plane strain given (its 33 component the first guess of eps_33),
// eps_33 found with sigma_33 = 0 to `tolerance` times the stress scale; the tangent is the
// in-plane one (its 33 row and column zero). Throws SolverError when the Newton on eps_33
// does not converge.
J2Update j2_update_plane_stress(const Material& material, const J2Hardening& hardening, const J2State& previous,
                                const Mandel& strain, double tolerance = 1e-12, J2Hold hold = J2Hold::none);

// The von Mises stress sqrt(3/2) |dev sigma|.
double von_mises(const Mandel& stress);

}  // namespace bemcontact::plasticity
