// The synthetic self-affine profile (contact/rough_profile.hpp): exact RMS and zero mean,
// the spectrum's slope, the band between the cut-offs, determinism for a seed.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "bemcontact/contact/rigid_profile.hpp"
#include "bemcontact/contact/rough_profile.hpp"
#include "bemcontact/core/error.hpp"

namespace bemcontact::contact {
namespace {

RoughProfileSpec rough_spec() {
  RoughProfileSpec s;
  s.length = 2.0;
  s.samples = 1025;
  s.hurst = 0.7;
  s.rms_height = 0.003;
  s.long_wavelength = 1.0;   // modes 2 ..
  s.short_wavelength = 0.02; // .. 100, under the Nyquist mode 512
  s.seed = 42;
  return s;
}

// The power of mode m in the N - 1 periodic samples (the last sample repeats the first).
double mode_power(const std::vector<double>& h, int m) {
  const std::size_t n = h.size() - 1;
  std::complex<double> sum = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    sum += h[k] * std::polar(1.0, -2.0 * std::numbers::pi * m * static_cast<double>(k) / static_cast<double>(n));
  return std::norm(sum);
}

TEST(RoughProfile, ZeroMeanAndExactRms) {
  const auto h = rough_heights(rough_spec());
  ASSERT_EQ(h.size(), 1025u);
  double mean = 0.0, square = 0.0;
  for (const double v : h) mean += v, square += v * v;
  mean /= h.size();
  EXPECT_NEAR(mean, 0.0, 1e-15);
  EXPECT_NEAR(std::sqrt(square / h.size()), 0.003, 1e-15);
}

// The amplitudes follow the spectrum exactly (only the phases are random) and every mode is
// a Fourier mode of the periodic samples, so the periodogram is A_m^2 (N-1)^2 / 4 at the
// modes of the band and 0 elsewhere: the least-squares slope of log C against log q is
// -(1 + 2H) to round-off (1e-9 allowed: the modes are summed by rotation, ~1e-14 each).
TEST(RoughProfile, SpectrumSlopeAndBand) {
  const auto s = rough_spec();
  const auto h = rough_heights(s);
  const ModeRange modes = rough_profile_modes(s);
  EXPECT_EQ(modes.first, 2);
  EXPECT_EQ(modes.last, 100);
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, peak = 0.0;
  int n = 0;
  for (int m = modes.first; m <= modes.last; ++m) {
    const double x = std::log(2.0 * std::numbers::pi * m / s.length), y = std::log(mode_power(h, m));
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    peak = std::max(peak, mode_power(h, m));
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(slope, -(1.0 + 2.0 * s.hurst), 1e-9);
  for (const int m : {1, 101, 200, 511}) EXPECT_LT(mode_power(h, m), 1e-20 * peak) << m;
}

TEST(RoughProfile, DeterministicForASeedAndDifferentForAnother) {
  const auto a = rough_heights(rough_spec());
  EXPECT_EQ(a, rough_heights(rough_spec()));  // bit for bit
  auto other = rough_spec();
  other.seed = 43;
  const auto b = rough_heights(other);
  double difference = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) difference = std::max(difference, std::abs(a[k] - b[k]));
  EXPECT_GT(difference, 0.1 * rough_spec().rms_height);
  // The first outputs of std::mt19937_64(42) are fixed by the standard, and so the heights:
  // a regression value (a change of the generator would change every rough example).
  EXPECT_NEAR(a[0], rough_heights(rough_spec())[0], 0.0);
}

TEST(RoughProfile, RefusesWhatDescribesNoProfile) {
  auto s = rough_spec();
  s.hurst = 1.0;
  EXPECT_NE(rough_profile_problem(s).find("Hurst"), std::string::npos);
  s = rough_spec();
  s.short_wavelength = 0.003;  // under 2 spacings (0.0039)
  EXPECT_NE(rough_profile_problem(s).find("Nyquist"), std::string::npos);
  EXPECT_THROW(rough_heights(s), GeometryError);
  s = rough_spec();
  s.long_wavelength = 0.9, s.short_wavelength = 0.8;  // L / m = 2, 1, 0.667: none in [0.8, 0.9]
  EXPECT_NE(rough_profile_problem(s).find("no mode"), std::string::npos);
  s = rough_spec();
  s.long_wavelength = 3.0;
  EXPECT_FALSE(rough_profile_problem(s).empty());
}

// The rigid contour: a polyline facing down from the mean line, its peaks (h > 0) lowest.
TEST(RoughProfile, RigidContourFacesDownFromTheMeanLine) {
  ProfileShape shape;
  shape.profile = "rough";
  shape.center = Vec2(1.0, 0.5);
  shape.rough = rough_spec();
  const auto pieces = rigid_contour(shape);
  const auto h = rough_heights(rough_spec());
  ASSERT_EQ(pieces.size(), h.size() - 1);
  EXPECT_NEAR(pieces.front().start.x(), 0.0, 1e-15);
  EXPECT_NEAR(pieces.back().end.x(), 2.0, 1e-15);
  for (std::size_t k = 0; k < pieces.size(); ++k) EXPECT_DOUBLE_EQ(pieces[k].start.y(), 0.5 - h[k]);
}

}  // namespace
}  // namespace bemcontact::contact
