#pragma once
// Synthetic self-affine rough profiles (a pure function: no I/O). A 1D profile whose power
// spectrum is C(q) ~ q^-(1 + 2H) between the long and short cut-off wavelengths (Hurst
// exponent H, fractal dimension 2 - H) [Persson2005], as a sum of
// Fourier modes of the profile's length with random phases, then shifted to zero mean and
// scaled to the exact RMS height over its samples.
#include <cstdint>
#include <string>
#include <vector>

#include "bemcontact/core/types.hpp"

namespace bemcontact::contact {

struct RoughProfileSpec {
  double length = 1.0;            // L: the samples span [0, L]; the profile is L-periodic
  int samples = 2;                // N >= 2 points, spacing L / (N - 1)
  double hurst = 0.8;             // H in (0, 1)
  double rms_height = 1.0;        // > 0
  double long_wavelength = 1.0;   // lambda_L <= L: the longest wavelength (roll-off)
  double short_wavelength = 0.1;  // lambda_S in [2 L / (N - 1), lambda_L]: the shortest
  std::uint64_t seed = 0;         // of std::mt19937_64: the phases
};

// Why `spec` describes no profile ("" when it does): a value out of range, cut-offs in the
// wrong order, a short cut-off under two sample spacings (Nyquist), no mode between them.
std::string rough_profile_problem(const RoughProfileSpec& spec);

// The modes m = 1, 2, ... (wavelength L / m) between the cut-offs.
struct ModeRange {
  int first = 1, last = 0;
};
ModeRange rough_profile_modes(const RoughProfileSpec& spec);

// The heights at x_k = k L / (N - 1), k = 0 .. N - 1:
//   h(x) = sum_m A_m cos(q_m x + phi_m),  q_m = 2 pi m / L,  A_m ~ sqrt(C(q_m)) ~ q_m^-(1/2 + H),
// phi_m = 2 pi u_m, u_m = (the m-th output of std::mt19937_64(seed) >> 11) * 2^-53 in
// increasing m: the engine's output is fixed by the standard, no library distribution is
// involved, so the heights are the same with every standard library. Then h - mean(h),
// scaled so that sqrt(mean(h^2)) = rms_height over the N samples. Throws GeometryError when
// rough_profile_problem is not empty. Cost: samples x modes rotations (the reader keeps
// samples <= 20000: at most 1e8, about a second; 1e5 samples of 5e4 modes took 15 s).
std::vector<double> rough_heights(const RoughProfileSpec& spec);

}  // namespace bemcontact::contact
