#include "bemcontact/contact/rough_profile.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <string>

#include "bemcontact/core/error.hpp"

namespace bemcontact::contact {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// A uniform number in [0, 1) from the engine's 53 high bits (not std::uniform_real_distribution,
// whose algorithm the standard leaves to the library).
double unit_uniform(std::mt19937_64& engine) { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }

}  // namespace

std::string rough_profile_problem(const RoughProfileSpec& s) {
  if (!(s.length > 0.0) || !std::isfinite(s.length)) return "the length must be > 0";
  if (s.samples < 2) return "needs at least 2 samples";
  if (!(s.hurst > 0.0 && s.hurst < 1.0)) return "the Hurst exponent must be in (0, 1)";
  if (!(s.rms_height > 0.0) || !std::isfinite(s.rms_height)) return "the RMS height must be > 0";
  if (!(s.long_wavelength > 0.0 && s.long_wavelength <= s.length))
    return "the long cut-off wavelength must be in (0, length]: the profile holds no longer mode";
  if (!(s.short_wavelength > 0.0 && s.short_wavelength <= s.long_wavelength))
    return "the short cut-off wavelength must be in (0, long cut-off]";
  const double spacing = s.length / (s.samples - 1);
  if (s.short_wavelength < 2.0 * spacing * (1.0 - 1e-12))
  {
    char twice[32];
    std::snprintf(twice, sizeof twice, "%.6g", 2.0 * spacing);
    return std::string("the short cut-off wavelength must span at least 2 sample spacings (") + twice +
           "; Nyquist): more samples or a longer cut-off";
  }
  const ModeRange modes = rough_profile_modes(s);
  if (modes.first > modes.last) return "no mode of wavelength length / m lies between the cut-offs: widen them";
  return "";
}

ModeRange rough_profile_modes(const RoughProfileSpec& s) {
  // Wavelengths L / m within the cut-offs, to round-off (a cut-off of exactly L / m keeps m).
  constexpr double tolerance = 1e-9;
  return {static_cast<int>(std::ceil(s.length / s.long_wavelength - tolerance)),
          static_cast<int>(std::floor(s.length / s.short_wavelength + tolerance))};
}

std::vector<double> rough_heights(const RoughProfileSpec& s) {
  if (const std::string problem = rough_profile_problem(s); !problem.empty())
    throw GeometryError("rough profile: " + problem);
  const ModeRange modes = rough_profile_modes(s);
  const std::size_t n = static_cast<std::size_t>(s.samples);
  const double spacing = s.length / (s.samples - 1);
  std::vector<double> h(n, 0.0);
  std::mt19937_64 engine(s.seed);
  for (int m = 1; m <= modes.last; ++m) {
    const double phase = kTwoPi * unit_uniform(engine);  // one draw per mode from m = 1: the
    if (m < modes.first) continue;                       // phases do not move with the cut-offs
    const double q = kTwoPi * m / s.length;
    const double amplitude = std::pow(q, -(0.5 + s.hurst));  // sqrt(C(q)), C ~ q^-(1+2H)
    // cos(q x_k + phase) by rotation, restarted every 256 samples (round-off stays ~1e-14).
    const std::complex<double> step = std::polar(1.0, q * spacing);
    std::complex<double> v;
    for (std::size_t k = 0; k < n; ++k) {
      if (k % 256 == 0) v = std::polar(1.0, q * spacing * static_cast<double>(k) + phase);
      h[k] += amplitude * v.real();
      v *= step;
    }
  }
  double mean = 0.0;
  for (const double value : h) mean += value;
  mean /= static_cast<double>(n);
  double square = 0.0;
  for (double& value : h) value -= mean, square += value * value;
  const double rms = std::sqrt(square / static_cast<double>(n));
  if (!(rms > 0.0)) throw GeometryError("rough profile: the samples are flat (no mode is resolved by them)");
  for (double& value : h) value *= s.rms_height / rms;
  return h;
}

}  // namespace bemcontact::contact
