// The independent half-space contact model: its flexibility against Hertz's closed-form
// surface displacements, its frictionless solution against Hertz, and its input checks.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/halfspace_model.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/reference/hertz.hpp"

namespace bemcontact::contact {
namespace {

const Material ball{432000.0, 0.32}, support{72000.0, 0.32};

std::vector<double> radii(double extent, int intervals) {
  std::vector<double> r;
  for (int i = 0; i <= intervals; ++i) r.push_back(extent * i / intervals);
  return r;
}

TEST(HalfSpaceModel, FlexibilityGivesHertzSurfaceDisplacements) {
  // Hertz pressure on the lower half-space: u_r ([Johnson1985, (3.41)]) and the indentation
  // profile u_z(0) - u_z(r) = pi p0 r^2 / (4 a) (1 - nu^2) / E inside the contact.
  const reference::HertzPointContact hertz{31.5, 1.0, reference::contact_modulus(ball, support)};
  const double a = hertz.contact_radius();
  const auto r = radii(1.5 * a, 45);
  const Matrix C = halfspace_surface_flexibility(r, support, false);
  const Index n = static_cast<Index>(r.size());
  Vector q = Vector::Zero(2 * n);
  for (Index i = 0; i < n; ++i) q[2 * i + 1] = -hertz.pressure(r[i]);  // pressing down
  const Vector u = C * q;
  double worst_radial = 0.0, worst_profile = 0.0, scale_radial = 0.0, scale_profile = 0.0;
  for (Index i = 1; i < n; ++i) {
    const auto exact = hertz.surface_displacement(support, r[i]);
    const double exact_profile = exact.indentation - hertz.surface_displacement(support, 0.0).indentation;
    worst_radial = std::max(worst_radial, std::abs(u[2 * i] - exact.radial));
    worst_profile = std::max(worst_profile, std::abs((u[1] - u[2 * i + 1]) - exact_profile));
    scale_radial = std::max(scale_radial, std::abs(exact.radial));
    scale_profile = std::max(scale_profile, std::abs(exact_profile));
  }
  // Linear hats on 30 intervals over the contact: the square-root edge of the pressure
  // limits the accuracy to about h^1.5.
  EXPECT_LT(worst_radial, 5e-3 * scale_radial);
  EXPECT_LT(worst_profile, 5e-3 * scale_profile);
}

TEST(HalfSpaceModel, FrictionlessSolutionIsHertz) {
  HalfSpaceSphereContact spec{ball, support, 1.0, 31.5, {}, true};
  const reference::HertzPointContact hertz{31.5, 1.0, reference::contact_modulus(ball, support)};
  spec.radii = radii(1.43 * hertz.contact_radius(), 40);
  const auto model = halfspace_sphere_model(spec);
  ContactProblem settings;
  settings.analysis = AnalysisType::axisymmetric;
  const auto history = solve_load_history(model.condensed, model.pairs, settings);
  EXPECT_NEAR(history.summary.contact_radius, hertz.contact_radius(), 5e-3 * hertz.contact_radius());
  EXPECT_NEAR(history.summary.centre_pressure, hertz.max_pressure(), 2e-3 * hertz.max_pressure());
  EXPECT_NEAR(-history.summary.approach, hertz.approach(), 2e-3 * hertz.approach());
  EXPECT_NEAR(history.summary.normal_force, 31.5, 1e-6 * 31.5);
}

TEST(HalfSpaceModel, RejectsBadInput) {
  HalfSpaceSphereContact spec{ball, support, 1.0, 31.5, {0.1, 0.2}, true};
  EXPECT_THROW(halfspace_sphere_model(spec), Error);  // not from the axis
  spec.radii = {0.0, 0.2, 0.1};
  EXPECT_THROW(halfspace_sphere_model(spec), Error);  // not increasing
  spec.radii = {0.0, 0.1, 0.2};
  spec.force = 0.0;
  EXPECT_THROW(halfspace_sphere_model(spec), Error);
}

}  // namespace
}  // namespace bemcontact::contact
