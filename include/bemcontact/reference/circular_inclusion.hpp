#pragma once
// A circular elastic inclusion (fibre) perfectly bonded in an infinite matrix under a
// remote uniform in-plane stress (plane strain or plane stress): the stress inside is
// uniform (Eshelby; Hashin). With kappa = 3 - 4 nu (plane strain) or (3 - nu)/(1 + nu)
// (plane stress) and mu the shear moduli, split the remote stress into its mean
// P = (s11 + s22)/2 and its deviator (Q, T) = ((s11 - s22)/2, s12):
//   P_in = P mu_f (kappa_m + 1) / (mu_m (kappa_f - 1) + 2 mu_f),
//   (Q, T)_in = (Q, T) mu_f (kappa_m + 1) / (mu_m + kappa_m mu_f).
// Derived from Eshelby's tensor of a circular cylinder, S_mean = 2/(kappa + 1) on the
// in-plane mean strain and S_dev = kappa/(kappa + 1) on the deviator (checked: equal
// materials give the remote stress, a hole 0, a rigid fibre (kappa_m + 1)/2 and
// (kappa_m + 1)/kappa_m, the known rigid-inclusion factors).
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

struct CircularInclusion {
  Material matrix, fibre;
  AnalysisType type = AnalysisType::plane_strain;
  double remote_s11 = 1.0, remote_s22 = 0.0, remote_s12 = 0.0;

  Stress stress_inside() const;  // s33: nu_f (s11 + s22) in plane strain, 0 in plane stress
};

}  // namespace bemcontact::reference
