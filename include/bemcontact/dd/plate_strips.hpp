#pragma once
// The decompositions of the thesis' validation (section IV.5.1): the plate in tension of
// II.7.1, Omega = ]-1,1[ x ]0,2[, E = 1e5, nu = 0.1, plane stress, p2 = P on y = 2,
// u2 = 0 and p1 = 0 on y = 0, u1 = 0 at the origin, cut into `strips` horizontal strips
// of height T = height / strips (height = 2 in the thesis). Elements of size about h: 2/h on the horizontal sides and
// max(1, round(T/h)) on the vertical ones (h = 1/6: 2 x 36, 3 x 32, 4 x 30 elements, as
// in Tables IV.2 and IV.3). Strips are named "strip1" (bottom) upwards; the interface
// between strip k and k+1 is "y<k>". Built in code for the studies (validate, benchmarks);
// examples/dd_strips_*.toml hold the same problems as files.
#include "bemcontact/dd/decomposition.hpp"

namespace bemcontact::dd {

struct PlateStripsSpec {
  int strips = 2;
  int elements_per_unit = 6;  // 1 / h
  double applied_stress = 1.0;
  Material material{100000.0, 0.1};
  AnalysisType analysis = AnalysisType::plane_stress;
  InterfaceMethod method = InterfaceMethod::mixed;
  double height = 2.0;  // of the whole plate (the thesis' 2; benchmarks stack taller plates)
};

DecompositionProblem plate_strips(const PlateStripsSpec& spec);

}  // namespace bemcontact::dd
