// Closed-form elastic fields of bemcontact::reference (II.7.1-II.7.6): each field is checked
// against the equations it must satisfy, not against itself:
//   equilibrium div sigma = 0 (with the hoop terms in axisymmetry and for the sphere),
//   Hooke: strains from u by finite differences = compliance * sigma (3D law, with s33),
//   boundary conditions on the loaded surfaces, and the numbers printed in the thesis.
//
// Finite differences: 4th-order central stencil, step h = 1e-3 * (length scale). Truncation
// error ~ (h/L)^4 ~ 1e-12 and round-off ~ eps / (h/L) ~ 1e-13, relative to the stress (or
// strain) scale, so the residual tolerance 1e-8 cannot hide a wrong term (which would give
// residuals of order 1).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "bemcontact/core/error.hpp"
#include "bemcontact/reference/cantilever.hpp"
#include "bemcontact/reference/curved_beam.hpp"
#include "bemcontact/reference/kirsch.hpp"
#include "bemcontact/reference/lame.hpp"
#include "bemcontact/reference/uniaxial_tension.hpp"

namespace ref = bemcontact::reference;
using bemcontact::AnalysisType;
using bemcontact::Material;
using bemcontact::Vec2;

namespace {

constexpr double kResidualTolerance = 1e-8;

template <class F>
auto derivative(F f, double x, double h) {
  return (-f(x + 2 * h) + 8.0 * f(x + h) - 8.0 * f(x - h) + f(x - 2 * h)) / (12.0 * h);
}

// 3D isotropic compliance: normal strains from normal stresses.
double normal_strain(const Material& m, double s_ii, double s_jj, double s_kk) {
  return (s_ii - m.poisson_ratio * (s_jj + s_kk)) / m.young_modulus;
}

struct Residuals {
  double equilibrium = 0.0;  // |div sigma| * length / stress_scale
  double hooke = 0.0;        // |strain(u) - C sigma| * E / stress_scale
  double plane_condition = 0.0;  // |e33| (plane strain) or |s33| (plane stress), scaled
};

// Plane field (x1, x2).
using PlaneU = std::function<Vec2(const Vec2&)>;
using PlaneS = std::function<ref::Stress(const Vec2&)>;

Residuals plane_residuals(const PlaneU& u, const PlaneS& s, const Material& m, AnalysisType type,
                          const Vec2& x, double length, double stress_scale) {
  const double h = 1e-3 * length;
  auto along = [&](int axis, auto component) {
    return [&, axis, component](double t) {
      Vec2 y = x;
      y[axis] = t;
      return component(y);
    };
  };
  auto s11 = [&](const Vec2& y) { return s(y).s11; };
  auto s22 = [&](const Vec2& y) { return s(y).s22; };
  auto s12 = [&](const Vec2& y) { return s(y).s12; };
  auto u1 = [&](const Vec2& y) { return u(y).x(); };
  auto u2 = [&](const Vec2& y) { return u(y).y(); };
  const double div1 = derivative(along(0, s11), x.x(), h) + derivative(along(1, s12), x.y(), h);
  const double div2 = derivative(along(0, s12), x.x(), h) + derivative(along(1, s22), x.y(), h);
  const double e11 = derivative(along(0, u1), x.x(), h);
  const double e22 = derivative(along(1, u2), x.y(), h);
  const double g12 = derivative(along(1, u1), x.y(), h) + derivative(along(0, u2), x.x(), h);
  const ref::Stress sx = s(x);
  const double G = m.shear_modulus();
  Residuals r;
  r.equilibrium = std::hypot(div1, div2) * length / stress_scale;
  const double scale = m.young_modulus / stress_scale;
  r.hooke = scale * std::max({std::abs(e11 - normal_strain(m, sx.s11, sx.s22, sx.s33)),
                              std::abs(e22 - normal_strain(m, sx.s22, sx.s11, sx.s33)),
                              std::abs(g12 - sx.s12 / G)});
  r.plane_condition = type == AnalysisType::plane_strain
                          ? scale * std::abs(normal_strain(m, sx.s33, sx.s11, sx.s22))
                          : std::abs(sx.s33) / stress_scale;
  return r;
}

// Axisymmetric field (r, z); s33 is the hoop stress.
using AxiU = std::function<Vec2(double, double)>;
using AxiS = std::function<ref::Stress(double, double)>;

Residuals axisymmetric_residuals(const AxiU& u, const AxiS& s, const Material& m, double r, double z,
                                 double length, double stress_scale) {
  const double h = 1e-3 * length;
  auto at_r = [&](auto f) { return [&, f](double t) { return f(t, z); }; };
  auto at_z = [&](auto f) { return [&, f](double t) { return f(r, t); }; };
  auto srr = [&](double a, double b) { return s(a, b).s11; };
  auto szz = [&](double a, double b) { return s(a, b).s22; };
  auto srz = [&](double a, double b) { return s(a, b).s12; };
  auto ur = [&](double a, double b) { return u(a, b).x(); };
  auto uz = [&](double a, double b) { return u(a, b).y(); };
  const ref::Stress sx = s(r, z);
  const double div_r = derivative(at_r(srr), r, h) + derivative(at_z(srz), z, h) + (sx.s11 - sx.s33) / r;
  const double div_z = derivative(at_r(srz), r, h) + derivative(at_z(szz), z, h) + sx.s12 / r;
  const double err = derivative(at_r(ur), r, h);
  const double ezz = derivative(at_z(uz), z, h);
  const double ett = u(r, z).x() / r;
  const double grz = derivative(at_z(ur), z, h) + derivative(at_r(uz), r, h);
  Residuals res;
  res.equilibrium = std::hypot(div_r, div_z) * length / stress_scale;
  const double scale = m.young_modulus / stress_scale;
  res.hooke = scale * std::max({std::abs(err - normal_strain(m, sx.s11, sx.s22, sx.s33)),
                                std::abs(ezz - normal_strain(m, sx.s22, sx.s11, sx.s33)),
                                std::abs(ett - normal_strain(m, sx.s33, sx.s11, sx.s22)),
                                std::abs(grz - sx.s12 / m.shear_modulus())});
  return res;
}

void expect_plane_field(const PlaneU& u, const PlaneS& s, const Material& m, AnalysisType type,
                        const std::vector<Vec2>& points, double length, double stress_scale) {
  for (const Vec2& x : points) {
    const Residuals r = plane_residuals(u, s, m, type, x, length, stress_scale);
    EXPECT_LT(r.equilibrium, kResidualTolerance) << "at " << x.transpose();
    EXPECT_LT(r.hooke, kResidualTolerance) << "at " << x.transpose();
    EXPECT_LT(r.plane_condition, 1e-14) << "at " << x.transpose();
  }
}

// Printed thesis tables truncate (not round) to two decimals: printed <= exact < printed + 0.01.
void expect_truncated(double exact, double printed) {
  EXPECT_GE(exact, printed - 1e-9);
  EXPECT_LT(exact, printed + 0.01);
}

}  // namespace

// ---------------------------------------------------------------- II.7.1 plate in tension
TEST(ReferencePlateTension, ThesisFieldSatisfiesEquationsAndBoundaryConditions) {
  for (AnalysisType type : {AnalysisType::plane_stress, AnalysisType::plane_strain}) {
    const ref::PlateInTension plate{1.0, Material{100000.0, 0.1}, type};
    expect_plane_field([&](const Vec2& x) { return plate.displacement(x); },
                       [&](const Vec2& x) { return plate.stress(x); }, plate.material, type,
                       {{0.3, 0.7}, {-0.9, 1.9}}, 2.0, 1.0);
    // p = (0, P) on x2 = 2, u2 = 0 and p1 = 0 on x2 = 0, u = 0 at O (II.7.1.1).
    EXPECT_NEAR(plate.stress({0.5, 2.0}).traction({0.0, 1.0}).x(), 0.0, 1e-15);
    EXPECT_DOUBLE_EQ(plate.stress({0.5, 2.0}).traction({0.0, 1.0}).y(), 1.0);
    EXPECT_EQ(plate.displacement({0.7, 0.0}).y(), 0.0);
    EXPECT_EQ(plate.stress({0.7, 0.0}).traction({0.0, -1.0}).x(), 0.0);
    EXPECT_EQ(plate.displacement({0.0, 0.0}).norm(), 0.0);
  }
  // II.7.1.2, plane stress: u1 = -nu P x / E, u2 = P y / E.
  const ref::PlateInTension plate{1.0, Material{100000.0, 0.1}};
  EXPECT_DOUBLE_EQ(plate.displacement({1.0, 2.0}).x(), -1e-6);
  EXPECT_DOUBLE_EQ(plate.displacement({1.0, 2.0}).y(), 2e-5);
}

// ------------------------------------------------------------------ II.7.2 cantilever
TEST(ReferenceCantilever, PrintedExactValues) {
  const ref::CantileverParabolicShear beam{100.0, 100.0, 1.0, Material{100.0, 0.3}};
  const Vec2 B{100.0, 50.0}, C{0.0, 50.0};
  // Table II.4, "Solution analytique": the closed form gives them exactly (1e-12 << 0.005).
  EXPECT_NEAR(beam.displacement(B).x(), -2.0, 1e-12);
  EXPECT_NEAR(beam.displacement(B).y(), 4.5, 1e-12);
  EXPECT_NEAR(beam.stress(C).s11, -4.0, 1e-12);
  for (double x : {0.0, 25.0, 100.0}) EXPECT_NEAR(beam.stress({x, 0.0}).s12, 1.0, 1e-15);
}

TEST(ReferenceCantilever, FieldSatisfiesEquilibriumAndHooke) {
  for (AnalysisType type : {AnalysisType::plane_stress, AnalysisType::plane_strain}) {
    const ref::CantileverParabolicShear beam{100.0, 100.0, 1.0, Material{100.0, 0.3}, type};
    expect_plane_field([&](const Vec2& x) { return beam.displacement(x); },
                       [&](const Vec2& x) { return beam.stress(x); }, beam.material, type,
                       {{10.0, 5.0}, {50.0, -20.0}, {90.0, 45.0}}, 100.0, 4.0);
  }
  // A longer, slender beam with another amplitude.
  const ref::CantileverParabolicShear slender{400.0, 40.0, 2.5, Material{210000.0, 0.25}};
  expect_plane_field([&](const Vec2& x) { return slender.displacement(x); },
                     [&](const Vec2& x) { return slender.stress(x); }, slender.material,
                     AnalysisType::plane_stress, {{37.0, 11.0}, {350.0, -15.0}}, 40.0, 200.0);
}

TEST(ReferenceCantilever, BoundaryConditionsOfTheHalfModel) {
  const double L = 100.0, H = 100.0;
  const ref::CantileverParabolicShear beam{L, H, 1.0, Material{100.0, 0.3}};
  for (double y : {-50.0, -20.0, 0.0, 13.0, 50.0}) {
    const double parabola = 1.0 - std::pow(2.0 * y / H, 2);
    // AB (x1 = L): p1 = 0, p2 = 1 - (2 x2 / H)^2.
    const Vec2 pAB = beam.stress({L, y}).traction({1.0, 0.0});
    EXPECT_NEAR(pAB.x(), 0.0, 1e-14);
    EXPECT_NEAR(pAB.y(), parabola, 1e-14);
    // OC (x1 = 0): p1 = 8 L x2 / H^2, p2 = -1 + (2 x2 / H)^2.
    const Vec2 pOC = beam.stress({0.0, y}).traction({-1.0, 0.0});
    EXPECT_NEAR(pOC.x(), 8.0 * L * y / (H * H), 1e-13);
    EXPECT_NEAR(pOC.y(), -parabola, 1e-14);
  }
  for (double x : {0.0, 30.0, 100.0}) {
    // Free edges x2 = +-H/2.
    EXPECT_NEAR(beam.stress({x, 50.0}).traction({0.0, 1.0}).norm(), 0.0, 1e-14);
    EXPECT_NEAR(beam.stress({x, -50.0}).traction({0.0, -1.0}).norm(), 0.0, 1e-14);
    // Axis OA of the half model: u1 = 0, p2 = 0 ([thesis.md, §II.7.2]) ...
    EXPECT_EQ(beam.displacement({x, 0.0}).x(), 0.0);
    EXPECT_EQ(beam.stress({x, 0.0}).traction({0.0, -1.0}).y(), 0.0);
  }
  // ... and not the printed "u2 = 0, p1 = 0": both are nonzero on the axis.
  EXPECT_GT(std::abs(beam.displacement({50.0, 0.0}).y()), 1.0);
  EXPECT_NEAR(beam.stress({50.0, 0.0}).traction({0.0, -1.0}).x(), -1.0, 1e-15);
  // Supports: u = 0 at O, u1 = 0 at C.
  EXPECT_EQ(beam.displacement({0.0, 0.0}).norm(), 0.0);
  EXPECT_NEAR(beam.displacement({0.0, 50.0}).x(), 0.0, 1e-15);
  // End shear resultant: Simpson's rule is exact for the parabola.
  auto p2 = [&](double y) { return beam.stress({L, y}).traction({1.0, 0.0}).y(); };
  const double simpson = H / 6.0 * (p2(-H / 2) + 4.0 * p2(0.0) + p2(H / 2));
  EXPECT_NEAR(simpson, beam.end_shear_force(), 1e-12);
}

// ------------------------------------------------------------------ II.7.3 Kirsch
TEST(ReferenceKirsch, MatchesPrintedPolarFormulasWithThetaFromX1) {
  const double P = 2.5, a = 1.0;
  const ref::KirschPlate plate{a, P, std::numbers::pi / 2, Material{30000.0, 0.25}};
  for (double r : {1.0, 1.7, 4.0}) {
    for (double t : {0.0, 0.4, 1.2, 2.0, -0.7}) {
      const double q = a * a / (r * r);
      // II.7.3.2 as printed (load along x2, theta from x1).
      const double srr = P / 2 * ((1 - q) - (1 - 4 * q + 3 * q * q) * std::cos(2 * t));
      const double stt = P / 2 * ((1 + q) + (1 + 3 * q * q) * std::cos(2 * t));
      const double srt = P / 2 * (1 + 2 * q - 3 * q * q) * std::sin(2 * t);
      const ref::PolarStress s = plate.polar_stress(r, t);
      EXPECT_NEAR(s.rr, srr, 1e-14);
      EXPECT_NEAR(s.tt, stt, 1e-14);
      EXPECT_NEAR(s.rt, srt, 1e-14);
    }
  }
}

TEST(ReferenceKirsch, HoleIsFreeAndConcentrationIsThreeWhereTheTangentIsAlongTheLoad) {
  const double P = 2.5, a = 1.3;
  const ref::KirschPlate plate{a, P, std::numbers::pi / 2, Material{30000.0, 0.25}};
  for (double t = 0.0; t < 2 * std::numbers::pi; t += 0.37) {
    const Vec2 x = a * Vec2(std::cos(t), std::sin(t));
    EXPECT_NEAR(plate.traction(x, -x / a).norm(), 0.0, 1e-14 * P) << t;  // n = -e_r
  }
  // Load along x2: 3P at (a, 0) (theta = 0 from x1, tangent along x2), -P at (0, a).
  EXPECT_NEAR(plate.polar_stress(a, 0.0).tt, 3 * P, 1e-14);
  EXPECT_NEAR(plate.stress({a, 0.0}).s22, 3 * P, 1e-14);
  EXPECT_NEAR(plate.polar_stress(a, std::numbers::pi / 2).tt, -P, 1e-14);
  // Load along x1: the roles swap.
  const ref::KirschPlate along_x1{a, P, 0.0, Material{30000.0, 0.25}};
  EXPECT_NEAR(along_x1.stress({0.0, a}).s11, 3 * P, 1e-14);
  // Far field: uniform s22 = P. The perturbation decays like (a/r)^2.
  const bemcontact::Vec2 far{3e4, 4e4};
  const ref::Stress s = plate.stress(far);
  EXPECT_NEAR(s.s22, P, 1e-8 * P);
  EXPECT_NEAR(s.s11, 0.0, 1e-8 * P);
  EXPECT_NEAR(s.s12, 0.0, 1e-8 * P);
}

TEST(ReferenceKirsch, FieldSatisfiesEquilibriumHookeAndQuarterModelSymmetry) {
  const double a = 1.0, P = 2.5;
  const std::vector<Vec2> points{{1.2, 0.3}, {0.1, 1.05}, {-2.0, 1.5}, {3.0, -4.0}, {0.8, -0.8}};
  for (AnalysisType type : {AnalysisType::plane_stress, AnalysisType::plane_strain}) {
    for (double angle : {std::numbers::pi / 2, 0.0, 0.3}) {
      const ref::KirschPlate plate{a, P, angle, Material{30000.0, 0.25}, type};
      expect_plane_field([&](const Vec2& x) { return plate.displacement(x); },
                         [&](const Vec2& x) { return plate.stress(x); }, plate.material, type,
                         points, a, 3 * P);
    }
    const ref::KirschPlate plate{a, P, std::numbers::pi / 2, Material{30000.0, 0.25}, type};
    for (double d : {1.0, 1.5, 5.0}) {
      // AB on x2 = 0: u2 = 0, s12 = 0; DE on x1 = 0: u1 = 0, s12 = 0 (II.7.3.1, II.7.3.3).
      // Round-off of cos(pi/2) ~ 6e-17 times |u|.
      const double u_scale = 1e-15 * plate.displacement({d, d}).norm();
      EXPECT_NEAR(plate.displacement({d, 0.0}).y(), 0.0, u_scale);
      EXPECT_NEAR(plate.stress({d, 0.0}).s12, 0.0, 1e-14);
      EXPECT_NEAR(plate.displacement({0.0, d}).x(), 0.0, u_scale);
      EXPECT_NEAR(plate.stress({0.0, d}).s12, 0.0, 1e-14);
    }
  }
}

TEST(ReferenceKirsch, FarFieldDisplacementIsUniaxialStrain) {
  // Far from the hole u tends to the plate-tension field: e22 = P/E', e11 = -nu' P/E'.
  const Material steel{30000.0, 0.25};
  for (AnalysisType type : {AnalysisType::plane_stress, AnalysisType::plane_strain}) {
    const ref::KirschPlate plate{1.0, 2.5, std::numbers::pi / 2, steel, type};
    const ref::PlateInTension far{2.5, steel, type};
    const Vec2 x{6e3, 8e3};
    // Hole terms in u are O(a^2 / r) relative to O(r): 1e-8 of the value at r = 1e4.
    EXPECT_LT((plate.displacement(x) - far.displacement(x)).norm(),
              1e-7 * far.displacement(x).norm());
  }
}

// ------------------------------------------------------------ II.7.4 cylinder in tension
TEST(ReferenceCylinderTension, ThesisTablesAndEquations) {
  const ref::CylinderInTension cyl{10.0, Material{1.0, 0.25}};
  // Table II.5 (-u_r on OA) and Table II.6 (u_z on z = 40).
  EXPECT_DOUBLE_EQ(-cyl.displacement(10.0, 0.0).x(), 25.0);
  EXPECT_DOUBLE_EQ(-cyl.displacement(60.0, 0.0).x(), 150.0);
  EXPECT_DOUBLE_EQ(-cyl.displacement(59.0, 40.0).x(), 147.5);
  EXPECT_DOUBLE_EQ(cyl.displacement(5.0, 40.0).y(), 400.0);
  EXPECT_DOUBLE_EQ(cyl.stress(30.0, 10.0).traction({0.0, 1.0}).y(), 10.0);  // p_z = P on BC
  EXPECT_EQ(cyl.stress(30.0, 10.0).traction({1.0, 0.0}).norm(), 0.0);       // free mantle
  for (auto [r, z] : {std::pair{5.0, 3.0}, {59.0, 40.0}}) {
    const auto res = axisymmetric_residuals([&](double a, double b) { return cyl.displacement(a, b); },
                                            [&](double a, double b) { return cyl.stress(a, b); },
                                            cyl.material, r, z, 60.0, 10.0);
    EXPECT_LT(res.equilibrium, kResidualTolerance);
    EXPECT_LT(res.hooke, kResidualTolerance);
  }
}

// ---------------------------------------------------------------- II.7.5 thick cylinder
TEST(ReferenceThickCylinder, OpenEndsThesisValues) {
  const ref::ThickCylinder tube{45.0, 90.0, 10.0, 0.0, Material{1.0, 0.25}, ref::CylinderEnds::open};
  EXPECT_NEAR(tube.radial_displacement(45.0), 862.5, 1e-10);
  EXPECT_NEAR(tube.radial_displacement(90.0), 600.0, 1e-10);
  // Table II.7, "Exact" column (printed values are truncated to 2 decimals).
  const std::vector<std::pair<double, double>> table{
      {49.5, 805.56}, {54.0, 760.00}, {58.5, 723.17}, {63.0, 693.21}, {67.5, 668.75},
      {72.0, 648.75}, {76.5, 632.42}, {81.0, 619.16}, {85.5, 608.48}};
  for (auto [r, u] : table) expect_truncated(tube.radial_displacement(r), u);
  // Table II.8 on z = 20: u_r, -s_rr, s_tt.
  expect_truncated(tube.radial_displacement(45.25), 858.98);
  expect_truncated(-tube.polar_stress(45.25).rr, 9.85);
  expect_truncated(tube.polar_stress(45.25).tt, 16.51);
  expect_truncated(-tube.polar_stress(50.0).rr, 7.46);
  expect_truncated(tube.polar_stress(50.0).tt, 14.13);
  expect_truncated(tube.radial_displacement(80.0), 621.87);
  // Printed (II.7.5.2) with sigma_0 = P / ((b/a)^2 - 1).
  const double s0 = 10.0 / 3.0, r = 61.0;
  EXPECT_NEAR(tube.radial_displacement(r), s0 * r * (1.25 * std::pow(90.0 / r, 2) + 0.75), 1e-10);
  EXPECT_NEAR(tube.polar_stress(r).rr, -s0 * (std::pow(90.0 / r, 2) - 1.0), 1e-13);
}

TEST(ReferenceThickCylinder, AllEndConditionsSatisfyTheEquations) {
  const Material m{1.0, 0.25};
  for (ref::CylinderEnds ends :
       {ref::CylinderEnds::open, ref::CylinderEnds::plane_strain, ref::CylinderEnds::closed}) {
    const ref::ThickCylinder tube{45.0, 90.0, 10.0, 3.0, m, ends};
    // Pressures on the walls: p = sigma n = -p_i n on r = a (n = -e_r), -p_o e_r on r = b.
    EXPECT_NEAR(tube.axisymmetric_stress(45.0, 7.0).traction({-1.0, 0.0}).x(), 10.0, 1e-12);
    EXPECT_NEAR(tube.axisymmetric_stress(90.0, 7.0).traction({1.0, 0.0}).x(), -3.0, 1e-12);
    for (auto [r, z] : {std::pair{46.0, 5.0}, {70.0, -30.0}, {89.0, 100.0}}) {
      const auto res = axisymmetric_residuals(
          [&](double a, double b) { return tube.axisymmetric_displacement(a, b); },
          [&](double a, double b) { return tube.axisymmetric_stress(a, b); }, m, r, z, 45.0, 20.0);
      EXPECT_LT(res.equilibrium, kResidualTolerance);
      EXPECT_LT(res.hooke, kResidualTolerance);
    }
  }
  // Open ends: free end faces. Closed ends: the end caps' load p_i pi a^2 - p_o pi b^2 is
  // carried by s_zz (trapezoid rule exact: s_zz is uniform).
  const ref::ThickCylinder open{45.0, 90.0, 10.0, 3.0, m, ref::CylinderEnds::open};
  EXPECT_EQ(open.axisymmetric_stress(60.0, 0.0).traction({0.0, 1.0}).norm(), 0.0);
  const ref::ThickCylinder closed{45.0, 90.0, 10.0, 3.0, m, ref::CylinderEnds::closed};
  const double cap_force = std::numbers::pi * (10.0 * 45.0 * 45.0 - 3.0 * 90.0 * 90.0);
  EXPECT_NEAR(closed.polar_stress(60.0).zz * std::numbers::pi * (90.0 * 90.0 - 45.0 * 45.0), cap_force,
              1e-9 * std::abs(cap_force));
  const ref::ThickCylinder strain{45.0, 90.0, 10.0, 3.0, m, ref::CylinderEnds::plane_strain};
  EXPECT_EQ(strain.axial_strain(), 0.0);
}

TEST(ReferenceThickCylinder, PlaneStrainCrossSectionForAQuarterAnnulus) {
  const Material m{200.0, 0.3};
  const ref::ThickCylinder tube{1.0, 2.0, 5.0, 1.0, m, ref::CylinderEnds::plane_strain};
  expect_plane_field([&](const Vec2& x) { return tube.displacement(x); },
                     [&](const Vec2& x) { return tube.stress(x); }, m, AnalysisType::plane_strain,
                     {{1.1, 0.2}, {0.5, 1.5}, {-1.2, 0.9}}, 1.0, 10.0);
  // Quarter-model symmetry lines: u2 = 0 and s12 = 0 on x2 = 0; u1 = 0 and s12 = 0 on x1 = 0.
  EXPECT_EQ(tube.displacement({1.5, 0.0}).y(), 0.0);
  EXPECT_NEAR(tube.stress({1.5, 0.0}).s12, 0.0, 1e-14);
  EXPECT_NEAR(tube.displacement({0.0, 1.5}).x(), 0.0, 1e-16);
  EXPECT_NEAR(tube.stress({0.0, 1.5}).s12, 0.0, 1e-14);
  // Inner wall pressure in Cartesian components at polar angle 0.5.
  const Vec2 n{std::cos(0.5), std::sin(0.5)};
  EXPECT_NEAR((tube.stress(n).traction(-n) - 5.0 * n).norm(), 0.0, 1e-13);
}

TEST(ReferenceThickCylinder, RejectsAnEmptyWall) {
  const ref::ThickCylinder bad{2.0, 1.0, 1.0, 0.0, Material{1.0, 0.3}};
  EXPECT_THROW(bad.radial_displacement(1.5), bemcontact::Error);
  const ref::ThickSphere flat{1.0, 1.0, 1.0, 0.0, Material{1.0, 0.3}};
  EXPECT_THROW(flat.spherical_stress(1.0), bemcontact::Error);
}

// ----------------------------------------------------------------- II.7.6 thick sphere
TEST(ReferenceThickSphere, ThesisValuesNeedPoissonPointThree) {
  const ref::ThickSphere sphere{1.0, 2.0, 100.0, 0.0, Material{200000.0, 0.3}};
  // Table II.9, printed precision: u in 1e-4 to 3 decimals, stresses to 2 decimals.
  EXPECT_NEAR(sphere.radial_displacement(1.0), 4.000e-4, 5e-8);
  EXPECT_NEAR(sphere.radial_displacement(2.0), 1.500e-4, 5e-8);
  EXPECT_NEAR(sphere.spherical_stress(1.0).tangential, 71.43, 5e-3);
  EXPECT_NEAR(sphere.spherical_stress(2.0).tangential, 21.43, 5e-3);
  EXPECT_NEAR(sphere.spherical_stress(1.0).radial, -100.0, 1e-12);
  EXPECT_NEAR(sphere.spherical_stress(2.0).radial, 0.0, 1e-12);
  // The printed nu = 0.25 misses the table: u(a) = 3.929e-4.
  const ref::ThickSphere printed{1.0, 2.0, 100.0, 0.0, Material{200000.0, 0.25}};
  EXPECT_GT(std::abs(printed.radial_displacement(1.0) - 4.000e-4), 5e-6);
  // (II.7.6.2) with the fractions restored.
  const double a3 = 1.0, b3 = 8.0, rho = 1.4, rho3 = rho * rho * rho;
  EXPECT_NEAR(sphere.spherical_stress(rho).radial, -100.0 * a3 * (b3 - rho3) / (rho3 * (b3 - a3)), 1e-12);
  EXPECT_NEAR(sphere.spherical_stress(rho).tangential, 100.0 * a3 * (b3 + 2 * rho3) / (2 * rho3 * (b3 - a3)),
              1e-12);
  EXPECT_NEAR(sphere.radial_displacement(rho),
              100.0 / 200000.0 * a3 / (b3 - a3) * (0.4 * rho + 0.65 * b3 / (rho * rho)), 1e-18);
}

TEST(ReferenceThickSphere, FieldSatisfiesSphericalAndAxisymmetricEquations) {
  const Material m{200000.0, 0.3};
  const ref::ThickSphere sphere{1.0, 2.0, 100.0, 20.0, m};
  for (double rho : {1.0, 1.3, 1.9}) {
    const double h = 1e-3;
    const auto s = sphere.spherical_stress(rho);
    // d s_rho / d rho + 2 (s_rho - s_tt) / rho = 0.
    const double div = derivative([&](double t) { return sphere.spherical_stress(t).radial; }, rho, h) +
                       2.0 * (s.radial - s.tangential) / rho;
    EXPECT_LT(std::abs(div) / 100.0, kResidualTolerance);
    // e_rho = du/drho, e_tt = u/rho, by the 3D law.
    const double e_rho = derivative([&](double t) { return sphere.radial_displacement(t); }, rho, h);
    EXPECT_LT(std::abs(e_rho - normal_strain(m, s.radial, s.tangential, s.tangential)) * m.young_modulus / 100.0,
              kResidualTolerance);
    EXPECT_LT(std::abs(sphere.radial_displacement(rho) / rho - normal_strain(m, s.tangential, s.radial, s.tangential)) *
                  m.young_modulus / 100.0,
              1e-12);
  }
  // Quarter model in (r, z): equilibrium with hoop terms, Hooke, pressure on the walls.
  for (auto [r, z] : {std::pair{1.2, 0.3}, {0.4, 1.5}, {1.0, 1.0}}) {
    const auto res = axisymmetric_residuals(
        [&](double a, double b) { return sphere.axisymmetric_displacement(a, b); },
        [&](double a, double b) { return sphere.axisymmetric_stress(a, b); }, m, r, z, 1.0, 100.0);
    EXPECT_LT(res.equilibrium, kResidualTolerance);
    EXPECT_LT(res.hooke, kResidualTolerance);
  }
  const Vec2 n{std::cos(0.7), std::sin(0.7)};
  EXPECT_NEAR((sphere.axisymmetric_stress(n.x(), n.y()).traction(-n) - 100.0 * n).norm(), 0.0, 1e-12);
  const Vec2 outer = 2.0 * n;
  EXPECT_NEAR((sphere.axisymmetric_stress(outer.x(), outer.y()).traction(n) + 20.0 * n).norm(), 0.0, 1e-12);
  // Symmetry plane z = 0 of the quarter model: u_z = 0, s_rz = 0.
  EXPECT_EQ(sphere.axisymmetric_displacement(1.5, 0.0).y(), 0.0);
  EXPECT_EQ(sphere.axisymmetric_stress(1.5, 0.0).s12, 0.0);
}

// ------------------------------------------------- curved bar under end couples (T&G 29)
TEST(ReferenceCurvedBeam, FreeArcsEndResultantsEquilibriumAndHooke) {
  const double a = 1.0, b = 2.5, M = 3.0;
  for (AnalysisType type : {AnalysisType::plane_stress, AnalysisType::plane_strain}) {
    const ref::CurvedBeamEndCouple beam{a, b, M, Material{1000.0, 0.3}, type};
    // Sector 0 < theta < 60 degrees: theta stays away from the branch cut of atan2.
    expect_plane_field([&](const Vec2& x) { return beam.displacement(x); },
                       [&](const Vec2& x) { return beam.stress(x); }, beam.material, type,
                       {{1.2, 0.3}, {1.0, 1.2}, {2.0, 1.0}, {0.9, 1.9}}, b, 10.0 * M / (b * b));
    // The arcs are free: s_rr = 0 at r = a and r = b.
    EXPECT_NEAR(beam.polar_stress(a).rr, 0.0, 1e-13 * M);
    EXPECT_NEAR(beam.polar_stress(b).rr, 0.0, 1e-13 * M);
    // End section: no force, moment -M about the centre (Gauss-Legendre, 5 points on 64
    // panels: exact to round-off for this smooth integrand).
    const double x5[] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
    const double w5[] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                         0.2369268850561891};
    double force = 0.0, moment = 0.0;
    const int panels = 64;
    for (int k = 0; k < panels; ++k) {
      const double lo = a + (b - a) * k / panels, hi = a + (b - a) * (k + 1) / panels;
      for (int q = 0; q < 5; ++q) {
        const double r = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x5[q], w = 0.5 * (hi - lo) * w5[q];
        force += w * beam.polar_stress(r).tt;
        moment += w * beam.polar_stress(r).tt * r;
      }
    }
    EXPECT_NEAR(force, 0.0, 1e-12 * M);
    EXPECT_NEAR(moment, -M, 1e-12 * M);
    EXPECT_GT(beam.polar_stress(a).tt, 0.0);  // M > 0 stretches the inner arc
  }
}
