// Axisymmetric reference cases of chapter II (II.7.4-II.7.6).
#include <cmath>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/reference/lame.hpp"
#include "bemcontact/reference/uniaxial_tension.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/case_support.hpp"

namespace bemcontact::validation {
namespace {



// Cylinder in tension (II.7.4): the field is linear, so linear elements reproduce it up
// to the quadrature accuracy of the ring integrals (~1e-10): tolerance 1e-5 (the issue's).
std::vector<Record> run_cylinder_tension(const Context& context) {
  const auto file = load_example(context, "cylinder_tension.toml");
  const auto& problem = file.problem;
  const double P = file.parameters.at("P");
  const reference::CylinderInTension exact{P, problem.body.material};
  return for_each_interpolation("cylinder-tension", problem, [&](const bem::ProblemDefinition& variant, std::vector<Record>& records) {
    const auto result = bem::solve_body(with_operator(context, variant), context.progress);
    const Index n10 = node_at(result.mesh, Vec2(10.0, 0.0));
    records.push_back(compare_relative("ur_r10", result.boundary.displacement[n10].x(),
                                       exact.displacement(10.0, 0.0).x(), 1e-5));
    const Index k = interior_point_at(result.interior, Vec2(20.0, 40.0));
    records.push_back(compare_relative("uz_z40", result.interior.displacement[k].y(), exact.displacement(20.0, 40.0).y(), 1e-5));
    records.push_back(compare_relative("szz_interior", result.interior.stress[k].s22, P, 1e-5));
    double u_error = 0.0, p_error = 0.0, s_error = 0.0;
    const double u_scale = exact.displacement(60.0, 80.0).norm();
    for (Index i = 0; i < result.mesh.node_count(); ++i) {
      const auto& node = result.mesh.nodes[i];
      u_error = std::max(u_error, (result.boundary.displacement[i] - exact.displacement(node.position.x(), node.position.y())).norm());
      p_error = std::max(p_error, (result.boundary.traction[i] - exact.stress(node.position.x(), node.position.y()).traction(node.normal)).norm());
    }
    for (std::size_t q = 0; q < result.interior.points.size(); ++q) {
      const auto& s = result.interior.stress[q];
      s_error = std::max({s_error, std::abs(s.s11), std::abs(s.s22 - P), std::abs(s.s12), std::abs(s.s33)});
    }
    records.push_back(compare_scaled("u_boundary_max_error", u_error, 0.0, u_scale, 1e-5));
    records.push_back(compare_scaled("p_boundary_max_error", p_error, 0.0, P, 1e-5));
    records.push_back(compare_scaled("s_interior_max_error", s_error, 0.0, P, 1e-5));
    return result.mesh.element_count();
  });
}

// Thick cylinder with free ends (II.7.5) against Lame: u_r on both surfaces within 0.1 %
// (thesis 0.07 %), interior s_rr and s_tt on z = 20 within 1 % for r >= 46 (the issue's).
std::vector<Record> run_thick_cylinder(const Context& context) {
  const auto file = load_example(context, "thick_cylinder.toml");
  const auto& problem = file.problem;
  const double a = file.parameters.at("a"), b = file.parameters.at("b"), P = file.parameters.at("P");
  const reference::ThickCylinder exact{a, b, P, 0.0, problem.body.material, reference::CylinderEnds::open};
  return for_each_interpolation("thick-cylinder", problem, [&](const bem::ProblemDefinition& variant, std::vector<Record>& records) {
    const auto result = bem::solve_body(with_operator(context, variant), context.progress);
    const double H = file.parameters.at("H");
    const Index ia = node_at(result.mesh, Vec2(a, H / 2)), ib = node_at(result.mesh, Vec2(b, H / 2));
    records.push_back(compare_relative("ur_a", result.boundary.displacement[ia].x(), exact.radial_displacement(a), 1e-3));
    records.push_back(compare_relative("ur_b", result.boundary.displacement[ib].x(), exact.radial_displacement(b), 1e-3));
    const Index k = interior_point_at(result.interior, Vec2(50.0, 20.0));
    records.push_back(compare_relative("srr_r50", result.interior.stress[k].s11, exact.polar_stress(50.0).rr, 1e-2));
    records.push_back(compare_relative("stt_r50", result.interior.stress[k].s33, exact.polar_stress(50.0).tt, 1e-2));
    double worst = 0.0;
    for (std::size_t q = 0; q < result.interior.points.size(); ++q) {
      const double r = result.interior.points[q].x();
      if (r < 46.0) continue;
      const auto s = exact.polar_stress(r);
      worst = std::max({worst, std::abs(result.interior.stress[q].s11 - s.rr), std::abs(result.interior.stress[q].s33 - s.tt)});
    }
    records.push_back(compare_scaled("s_interior_max_error_r46", worst, 0.0, P, 1e-2));
    return result.mesh.element_count();
  });
}

// Thick sphere (II.7.6, nu = 0.3), convergence study on 20, 40 (the thesis' mesh) and 80
// elements. At 40 elements we measure u within 0.2 % / 0.31 % and s_tt within 0.45 % /
// 0.30 % (inner / outer), so that mesh is held to the thesis' own errors (0.35 % on u,
// 0.7 % on s_tt); the 0.3 % is met from 80 elements on; 20 elements are held to
// four times the 40-element bounds (second order). s_rr = -P on the inner surface within
// 0.5 %. Quadratic elements: the same bounds, and the observed order.
std::vector<Record> run_thick_sphere(const Context& context) {
  const auto file = load_example(context, "thick_sphere.toml");
  const double a = file.parameters.at("a"), b = file.parameters.at("b"), P = file.parameters.at("P");
  reference::ThickSphere exact;
  exact.inner_radius = a;
  exact.outer_radius = b;
  exact.inner_pressure = P;
  exact.material = file.problem.body.material;
  std::vector<Record> records;
  for (Interpolation interpolation : {Interpolation::linear, Interpolation::quadratic}) {
  const bool quadratic = interpolation == Interpolation::quadratic;
  double previous_error = 0.0;
  for (int factor : {1, 2, 4}) {  // 20, 40, 80 elements
    auto problem = file.problem;
    problem.mesh.interpolation = interpolation;
    for (auto& piece : problem.body.pieces) piece.elements = std::max(1, piece.elements * factor / 2);
    problem.interior_points.clear();
    const auto result = bem::solve_body(with_operator(context, problem), context.progress);
    const double c = std::sqrt(0.5);
    const Index ia = node_at(result.mesh, Vec2(a * c, a * c)), ib = node_at(result.mesh, Vec2(b * c, b * c));
    const Vec2 er(c, c);
    auto hoop = [&](Index i) { return result.boundary.stress[i].s33; };
    auto radial = [&](Index i) {
      const auto& s = result.boundary.stress[i];
      Mat2 m;
      m << s.s11, s.s12, s.s12, s.s22;
      return er.dot(m * er);
    };
    const std::size_t first = records.size();
    const double urho_a = result.boundary.displacement[ia].dot(er), urho_b = result.boundary.displacement[ib].dot(er);
    const double tol_u = factor == 4 ? 3e-3 : (factor == 2 ? 3.5e-3 : 1.4e-2);
    const double tol_s = factor == 4 ? 3e-3 : (factor == 2 ? 7e-3 : 2.8e-2);
    records.push_back(compare_relative("urho_a", urho_a, exact.radial_displacement(a), tol_u));
    records.push_back(compare_relative("urho_b", urho_b, exact.radial_displacement(b), tol_u));
    records.push_back(compare_relative("stt_a", hoop(ia), exact.spherical_stress(a).tangential, tol_s));
    records.push_back(compare_relative("stt_b", hoop(ib), exact.spherical_stress(b).tangential, tol_s));
    records.push_back(compare_relative("srr_a", radial(ia), -P, 5e-3));
    // Max error of u over all boundary nodes, for the observed order.
    double u_error = 0.0;
    for (Index i = 0; i < result.mesh.node_count(); ++i) {
      const Vec2 x = result.mesh.nodes[i].position;
      u_error = std::max(u_error, (result.boundary.displacement[i] - exact.axisymmetric_displacement(x.x(), x.y())).norm());
    }
    u_error /= exact.radial_displacement(a);
    if (previous_error > 0.0)
      // Quadratic: third order, measured 2.69 (20-40, pre-asymptotic) and 2.84 (40-80).
      records.push_back(require_at_least("order_u_boundary", observed_order(previous_error, u_error, 2.0),
                                         quadratic ? (factor == 4 ? 2.8 : 2.5) : 1.4));
    previous_error = u_error;
    tag(records, first, "thick-sphere",
        {{"interpolation", to_string(interpolation)}, {"elements", std::to_string(result.mesh.element_count())}});
  }
  }
  return records;
}

}  // namespace

std::vector<Case> axisymmetric_cases() {
  return {
      {"cylinder-tension", "II.7.4", "solid cylinder in tension, axisymmetric (exact linear field)", run_cylinder_tension},
      {"thick-cylinder", "II.7.5", "thick cylinder under internal pressure, free ends (Lame)", run_thick_cylinder},
      {"thick-sphere", "II.7.6", "thick sphere under internal pressure, 20/40/80 elements", run_thick_sphere},
  };
}

}  // namespace bemcontact::validation
