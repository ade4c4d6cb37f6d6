#pragma once
// A fibre composite cross-section, built in code for the validation and the benchmarks:
// a square matrix ]-W, W[^2 holding n x n circular fibres of radius R on a square grid of
// pitch `pitch` centred on the origin, each fibre a subdomain bonded to the matrix along
// its circle (four quarter arcs, interfaces "fibre<k>_q<j>"). Remote uniaxial stress sigma
// along x on the faces x = +-W (the faces y = +-W free); the matrix's rigid motion is
// fixed by point constraints at (-W, 0) (u1, u2) and (W, 0) (u2), which carry no
// reaction. Plane strain by default. Fibres are named "fibre1" ... row by row from the
// bottom left; the matrix is "matrix".
#include "bemcontact/dd/decomposition.hpp"

namespace bemcontact::dd {

struct FibreCompositeSpec {
  int fibres_per_side = 1;
  double fibre_radius = 1.0;
  double pitch = 4.0;          // centre-to-centre distance of neighbouring fibres
  double half_width = 30.0;    // W
  int elements_per_quarter = 8;  // on each quarter arc of a fibre
  int elements_per_side = 24;    // on each side of the square
  double applied_stress = 1.0;
  Material matrix{3000.0, 0.35};
  Material fibre{70000.0, 0.22};
  AnalysisType analysis = AnalysisType::plane_strain;
  InterfaceMethod method = InterfaceMethod::conforming;  // with the balancing preconditioner
};

DecompositionProblem fibre_composite(const FibreCompositeSpec& spec);

// Centre of fibre k (0-based, row by row from the bottom left).
Vec2 fibre_centre(const FibreCompositeSpec& spec, int k);

}  // namespace bemcontact::dd
