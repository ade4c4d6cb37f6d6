// Contact reference cases of chapter V: Hertz (V.5.2.3), Spence (V.5.2.4), the thesis'
// flat punch (V.5.1) and a rigid punch on a half-plane (closed form).
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Dense>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/halfspace_model.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/reference/flat_punch.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "bemcontact/reference/spence.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/contact_support.hpp"

namespace bemcontact::validation {

HertzFit fit_hertz_profile(const std::vector<contact::PairResult>& pairs, double window) {
  double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;
  for (const auto& pair : pairs) {
    const double r = std::abs(pair.coordinate);
    if (r <= 1e-12 * window || r >= window || pair.status == contact::PairStatus::open) continue;
    const double x = r * r, y = pair.p_n * pair.p_n;
    s0 += 1, s1 += x, s2 += x * x, t0 += y, t1 += x * y;
  }
  const double det = s0 * s2 - s1 * s1;
  const double intercept = (s2 * t0 - s1 * t1) / det, slope = (s0 * t1 - s1 * t0) / det;
  HertzFit fit;
  fit.p0 = std::sqrt(std::max(intercept, 0.0));
  fit.a = slope < 0.0 ? std::sqrt(-intercept / slope) : 0.0;
  return fit;
}

CentredHertzFit fit_hertz_profile_free_centre(const std::vector<contact::PairResult>& pairs, double first,
                                              double last) {
  CentredHertzFit out;
  if (!(first < last)) return out;
  const double middle = 0.5 * (first + last), window = 0.4 * (last - first);
  // Normal equations of the quadratic in s = x - middle (3 x 3).
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for (const auto& pair : pairs) {
    const double s = pair.coordinate - middle;
    if (pair.status == contact::PairStatus::open || std::abs(s) >= window) continue;
    const Eigen::Vector3d basis(1.0, s, s * s);
    normal += basis * basis.transpose();
    right += basis * (pair.p_n * pair.p_n);
  }
  const Eigen::Vector3d c = normal.ldlt().solve(right);
  if (!(c[2] < 0.0)) return out;
  const double shift = -c[1] / (2.0 * c[2]);
  const double p0_squared = c[0] + c[1] * shift + c[2] * shift * shift;
  out.centre = middle + shift;
  out.fit.p0 = std::sqrt(std::max(p0_squared, 0.0));
  out.fit.a = std::sqrt(std::max(-p0_squared / c[2], 0.0));
  return out;
}

double algorithm_difference(const contact::ContactResult& a, const contact::ContactResult& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.pairs.size() && i < b.pairs.size(); ++i)
    worst = std::max({worst, std::abs(a.pairs[i].p_n - b.pairs[i].p_n), std::abs(a.pairs[i].p_t - b.pairs[i].p_t)});
  return worst / a.summary.peak_pressure;
}

// The thesis' algorithm against Newton on the same equal steps: adaptive stepping follows
// each algorithm's own pair states, and a pair at a zone's edge that the two settle
// differently (within the thesis' tolerance xi) gives them different steps, whose paths
// differ by the stepping's error, not the solvers'.
AlgorithmComparison compare_algorithms(const Context& context, const contact::ContactProblem& problem) {
  auto newton = problem;
  newton.adaptive = false;
  newton.solver.algorithm = contact::Algorithm::newton;
  auto thesis = newton;
  thesis.solver.algorithm = contact::Algorithm::thesis;
  AlgorithmComparison out{contact::solve_contact(with_operator(context, newton), context.progress),
                          contact::solve_contact(with_operator(context, thesis), context.progress), 0.0};
  out.difference = algorithm_difference(out.newton, out.thesis);
  return out;
}

io::ContactFile load_contact_example(const Context& context, const std::string& file,
                                     const io::ParameterOverrides& overrides) {
  return io::read_contact_file(context.examples_dir + "/" + file, overrides);
}

double flat_punch_max_error(const std::vector<contact::PairResult>& pairs, const reference::FlatPunchPlane& exact) {
  double worst = 0.0;
  for (const auto& pair : pairs)
    if (std::abs(pair.coordinate) <= 0.8 * exact.half_width)
      worst = std::max(worst, std::abs(-pair.p_n / exact.pressure(pair.coordinate) - 1.0));
  return worst;
}

namespace {


// Nodal value at x1 = x by linear interpolation between the pairs around it.
double pressure_at(const std::vector<contact::PairResult>& pairs, double x) {
  const contact::PairResult* below = nullptr;
  const contact::PairResult* above = nullptr;
  for (const auto& p : pairs) {
    if (p.coordinate <= x && (!below || p.coordinate > below->coordinate)) below = &p;
    if (p.coordinate >= x && (!above || p.coordinate < above->coordinate)) above = &p;
  }
  if (!below) return -above->p_n;
  if (!above || above == below) return -below->p_n;
  const double f = (x - below->coordinate) / (above->coordinate - below->coordinate);
  return -((1 - f) * below->p_n + f * above->p_n);
}

double fitted_p0(const std::vector<contact::PairResult>& pairs, double a) { return fit_hertz_profile(pairs, 0.8 * a).p0; }

// Ball on a support (V.5.2.3): a, p0, delta within 2 % of Hertz (thesis: 1.2 %, 0.7 %,
// 2.2 %), the profile within 3 % of p0 for 0 < r < 0.9a (the axis pair on its own, 2 %), Huber's axis stresses within 3 % of
// p0, and the two algorithms against each other.
std::vector<Record> run_hertz_sphere(const Context& context) {
  std::vector<Record> records;
  const auto file = load_contact_example(context, "contact_hertz_sphere.toml");
  const double R = file.parameters.at("R");
  struct Load { double E_ball, P; };
  for (const Load load : {Load{72000.0, 10.0}, Load{216000.0, 10.0}, Load{432000.0, 10.0}, Load{432000.0, 31.5}}) {
    auto problem = file.problem;
    problem.elastic(0).material.young_modulus = load.E_ball;
    problem.forces.at(0).force = -load.P;
    const bool last = load.P == 31.5;
    const auto hertz = reference::hertz_point_contact(load.P, R, problem.elastic(0).material,
                                                      std::numeric_limits<double>::infinity(), problem.elastic(1).material);
    const double a = hertz.contact_radius(), p0 = hertz.max_pressure();
    if (last)
      for (int k = 1; k <= 16; ++k) problem.bodies[1].regions[0].interior_points.push_back({Vec2(0.02 * a, -k * a / 8.0), true, {}});
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    const std::size_t first = records.size();
    records.push_back(compare_relative("a", result.summary.contact_radius, a, 0.02));
    // p0 from the profile (fitted_p0); the pair on the axis on its own: collocation at r = 0
    // gives it a value a few per cent high that grows slowly with refinement.
    double axis = 0;
    for (const auto& pair : result.pairs)
      if (pair.coordinate <= 1e-12) axis = -pair.p_n;
    records.push_back(compare_relative("p0", fitted_p0(result.pairs, a), p0, 0.02));
    records.push_back(compare_relative("p0_axis_node", axis, p0, 0.02));
    records.push_back(compare_relative("delta", -result.summary.approach, hertz.approach(), 0.02));
    double profile = 0.0;
    for (const auto& pair : result.pairs)
      if (pair.coordinate > 1e-12 && pair.coordinate < 0.9 * a) profile = std::max(profile, std::abs(-pair.p_n - hertz.pressure(pair.coordinate)) / p0);
    records.push_back(compare_scaled("pressure_profile_max_error", profile, 0.0, 1.0, 0.03));
    records.push_back(require_at_least("newton_iterations", result.summary.newton_iterations, 1));
    if (last) {
      const double nu = problem.elastic(1).material.poisson_ratio;
      double szz = 0.0, srr = 0.0, tau = 0.0, tau_max = 0.0, tau_depth = 0.0;
      const auto& interior = result.interior[1];
      for (std::size_t k = 0; k < interior.points.size(); ++k) {
        if (std::abs(interior.points[k].x() - 0.02 * a) > 1e-12 * a) continue;  // the example's grid
        const double depth = -interior.points[k].y();
        const auto exact = hertz.axis_stress(nu, depth);
        const auto& s = interior.stress[k];
        szz = std::max(szz, std::abs(s.s22 - exact.s22) / p0);
        srr = std::max(srr, std::abs(s.s11 - exact.s11) / p0);
        const double t = 0.5 * std::abs(s.s11 - s.s22);
        tau = std::max(tau, std::abs(t - 0.5 * std::abs(exact.s11 - exact.s22)) / p0);
        if (t > tau_max) tau_max = t, tau_depth = depth;
      }
      const auto huber = reference::huber_max_shear_on_axis(nu);
      records.push_back(compare_scaled("axis_szz_max_error", szz, 0.0, 1.0, 0.03));
      records.push_back(compare_scaled("axis_srr_max_error", srr, 0.0, 1.0, 0.03));
      records.push_back(compare_scaled("axis_tau_max_error", tau, 0.0, 1.0, 0.03));
      records.push_back(compare_relative("tau_max_over_p0", tau_max / p0, huber.shear_over_p0, 0.03));
      // Sampled every a/8: the depth of the maximum is known to +- a/16.
      records.push_back(compare_scaled("tau_max_depth_over_a", tau_depth / a, huber.depth_over_a, 1.0, 0.0625));
      auto thesis = problem;
      thesis.solver.algorithm = contact::Algorithm::thesis;
      thesis.drop_interior_points();
      const auto other = contact::solve_contact(with_operator(context, thesis), context.progress);
      // xi = 1e-8 on relative changes: the algorithms agree to ~1e-6 of the peak pressure
      // (one frictionless step: no stepping).
      records.push_back(compare_scaled("thesis_vs_newton_max_difference", algorithm_difference(result, other), 0.0, 1.0, 1e-4));
      records.push_back(require_at_least("thesis_kalker_iterations", other.summary.kalker_iterations, 1));
      records.push_back(require_at_least("thesis_gmres_cycles", other.summary.gmres_cycles, 1));
    }
    tag(records, first, "hertz-sphere", {{"E_ball", number_text(load.E_ball)}, {"P", number_text(load.P)}});
  }
  return records;
}

// Spence (V.5.2.4): c/a within 0.03 of (E.1) (uncoupled model) and of the coupled value
// 0.513 ([thesis.md, Spence's (E.1)]); friction lowers a and raises p0; c/a for 1, 4, 16, 64 steps.
// The thesis' ball (a/R = 0.07) sits about 0.02 below the half-space values: the curvature
// of the ball tilts its surface by r/R, which its large normal displacement turns into a
// radial one of the size of Spence's coupling. The tolerance 0.03 holds that O(a/R) term;
// with R four times larger the ball lands within 0.01 of the half-space value.
std::vector<Record> run_spence_sphere(const Context& context) {
  std::vector<Record> records;
  auto file = load_contact_example(context, "contact_spence_sphere.toml");
  file.problem.drop_interior_points();  // the stress grid is for plots, not checked here
  auto frictionless = file.problem;
  frictionless.set_friction(0.0);
  frictionless.increments = 1;
  const auto reference_result = contact::solve_contact(with_operator(context, frictionless), context.progress);
  const double gamma = reference::spence_gamma(file.problem.elastic(0).material, file.problem.elastic(1).material);
  for (const double beta : {0.1, 0.6}) {
    const std::size_t first = records.size();
    const double spence = reference::spence_stick_ratio(beta, std::abs(gamma));
    auto problem = file.problem;
    problem.set_friction(beta);
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    const double c_over_a = result.summary.stick_ratio();
    const double coupled = beta == 0.1 ? 0.513 : 0.9997;  // [thesis.md, Spence's (E.1)], 640 steps
    records.push_back(compare_scaled("c_over_a", c_over_a, coupled, 1.0, 0.03));
    records.push_back(report_value("steps_taken_adaptive", result.steps_taken));
    auto uncoupled = problem;
    uncoupled.tangential_coupling = false;
    const auto u = contact::solve_contact(with_operator(context, uncoupled), context.progress);
    records.push_back(compare_scaled("c_over_a_uncoupled_vs_E1", u.summary.stick_ratio(),
                                     spence, 1.0, 0.03));
    records.push_back(require_at_least("a_decrease_with_friction",
                                       reference_result.summary.contact_radius - result.summary.contact_radius, 0.0));
    records.push_back(require_at_least("p0_increase_with_friction",
                                       result.summary.centre_pressure - reference_result.summary.centre_pressure, 0.0));
    for (const int steps : {1, 4, 64}) {
      auto history = problem;
      history.increments = steps;
      const auto h = contact::solve_contact(with_operator(context, history), context.progress);
      const double ratio = h.summary.stick_ratio();
      // The history matters only until the steps resolve the growth of the stick zone:
      // 64 steps must agree with 16 to 0.01; 1 and 4 steps are reported against 16.
      records.push_back(steps == 64 ? compare_scaled("c_over_a_64_steps", ratio, c_over_a, 1.0, 0.01)
                                    : report_only("c_over_a_" + std::to_string(steps) + "_steps", ratio, c_over_a));
    }
    if (beta == 0.1) {
      // Spence's theory is the limit a/R -> 0 of the ball: the same contact radius with R
      // four times larger (P / 4) brings c/a to the half-space value (spence-halfspace).
      const double R = file.parameters.at("R"), P = file.parameters.at("P");
      auto flatter = load_contact_example(context, "contact_spence_sphere.toml", {{"R", 4.0 * R}, {"P", P / 4.0}}).problem;
      flatter.drop_interior_points();
      flatter.set_friction(beta);
      const auto f = contact::solve_contact(with_operator(context, flatter), context.progress);
      records.push_back(compare_scaled("c_over_a_R4", f.summary.stick_ratio(), coupled, 1.0,
                                       0.01));
      // And 16 times larger: the O(a/R) term shrinks 4-fold at each step (measured 0.491,
      // 0.504, 0.507 at 30 elements), then the mesh: 0.509, 0.513 at 60, 120 elements.
      const auto sixteen = [&](int elements) {
        auto p = load_contact_example(context, "contact_spence_sphere.toml",
                                      {{"R", 16.0 * R}, {"P", P / 16.0}, {"contact_elements", elements}}).problem;
        p.drop_interior_points();
        p.set_friction(beta);
        return contact::solve_contact(with_operator(context, p), context.progress).summary.stick_ratio();
      };
      const double c16 = sixteen(30);
      records.push_back(report_only("c_over_a_R16", c16, coupled));
      records.push_back(require_at_least("a_over_R_convergence_R_to_R4",
                                         std::abs(c_over_a - coupled) - std::abs(f.summary.stick_ratio() - coupled), 0.0));
      records.push_back(require_at_least("a_over_R_convergence_R4_to_R16",
                                         std::abs(f.summary.stick_ratio() - coupled) - std::abs(c16 - coupled), 0.0));
      records.push_back(report_only("c_over_a_R16_60_elements", sixteen(60), coupled));
      records.push_back(compare_relative("c_over_a_R16_120_elements", sixteen(120), coupled, 0.01));
      const auto algorithms = compare_algorithms(context, problem);
      records.push_back(compare_scaled("thesis_vs_newton_max_difference", algorithms.difference, 0.0, 1.0, 1e-4));
      records.push_back(compare_scaled("thesis_c_over_a", algorithms.thesis.summary.stick_ratio(),
                                       algorithms.newton.summary.stick_ratio(), 1.0, 1e-3));
    }
    tag(records, first, "spence-sphere", {{"beta", number_text(beta)}, {"increments", number_text(problem.increments)},
                                          {"spence_E1", number_text(spence)}});
  }
  return records;
}

// Spence's theory in its own setting: the thesis' ball case (materials, R, P of
// contact_spence_sphere.toml) on the independent half-space model (Boussinesq-Cerruti ring
// kernels, Hertz's paraboloid gap), solved by the same contact solver. Frictionless: a, p0
// and delta within 0.5 % of Hertz (60 hat elements over 1.43 a). With friction: c/a within
// 0.01 of (E.1) when uncoupled (the approximation (E.1) makes) and of the coupled value
// 0.513 / 0.9997 ([thesis.md, Spence's (E.1)]). This checks the solver, the incremental Coulomb law
// and the measure of c apart from the BEM bodies.
std::vector<Record> run_spence_halfspace(const Context& context) {
  std::vector<Record> records;
  const auto file = load_contact_example(context, "contact_spence_sphere.toml");
  const double R = file.parameters.at("R"), P = file.parameters.at("P");
  const auto& sphere = file.problem.elastic(0).material;
  const auto& flat = file.problem.elastic(1).material;
  const reference::HertzPointContact hertz{P, R, reference::contact_modulus(sphere, flat)};
  const double a = hertz.contact_radius();
  contact::HalfSpaceSphereContact spec{sphere, flat, R, P, {}, true};
  const int intervals = 60;
  for (int i = 0; i <= intervals; ++i) spec.radii.push_back(1.43 * a * i / intervals);
  const auto coupled_model = contact::halfspace_sphere_model(spec);
  auto uncoupled_model = coupled_model;
  contact::drop_tangential_coupling(uncoupled_model.condensed);

  auto settings = file.problem;
  settings.set_friction(0.0);
  settings.increments = 1;
  std::size_t first = records.size();
  const auto frictionless = contact::solve_load_history(coupled_model.condensed, coupled_model.pairs, settings);
  records.push_back(compare_relative("a", frictionless.summary.contact_radius, a, 0.005));
  records.push_back(compare_relative("p0", frictionless.summary.centre_pressure, hertz.max_pressure(), 0.005));
  records.push_back(compare_relative("delta", -frictionless.summary.approach, hertz.approach(), 0.005));
  tag(records, first, "spence-halfspace", {{"beta", "0"}});

  const double gamma = std::abs(reference::spence_gamma(sphere, flat));
  for (const double beta : {0.1, 0.6}) {
    first = records.size();
    settings.set_friction(beta);
    settings.increments = file.problem.increments;
    const double spence = reference::spence_stick_ratio(beta, gamma);
    const double coupled_reference = beta == 0.1 ? 0.513 : 0.9997;  // [thesis.md, Spence's (E.1)], 640 steps
    const auto u = contact::solve_load_history(uncoupled_model.condensed, uncoupled_model.pairs, settings);
    const auto c = contact::solve_load_history(coupled_model.condensed, coupled_model.pairs, settings);
    records.push_back(compare_scaled("c_over_a_uncoupled_vs_E1", u.summary.stick_ratio(),
                                     spence, 1.0, 0.01));
    records.push_back(compare_scaled("c_over_a", c.summary.stick_ratio(),
                                     coupled_reference, 1.0, 0.01));
    tag(records, first, "spence-halfspace", {{"beta", number_text(beta)}, {"increments", number_text(settings.increments)},
                                             {"spence_E1", number_text(spence)}});
  }
  return records;
}

// Thesis' flat punch (V.5.1), reconstructed geometry: p_n(0), p_n(4.68), c next to the
// thesis' numbers. The geometry is a reconstruction (the figure is missing), so these are
// informational records (tolerance 100 %): they show the gap, they do not validate.
std::vector<Record> run_flat_punch(const Context& context) {
  std::vector<Record> records;
  const auto file = load_contact_example(context, "contact_flat_punch.toml");
  struct Thesis { double beta, p0, pI, c; };
  for (const Thesis t : {Thesis{0.05, 1.39, 6.51, 2.90}, Thesis{0.10, 1.43, 6.37, 3.87}}) {
    const std::size_t first = records.size();
    auto problem = file.problem;
    problem.set_friction(t.beta);
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    records.push_back(report_only("p_n_at_0_vs_thesis", pressure_at(result.pairs, 0.0), t.p0));
    records.push_back(report_only("p_n_at_4.68_vs_thesis", pressure_at(result.pairs, 4.68), t.pI));
    records.push_back(report_only("c_vs_thesis", result.summary.stick_radius, t.c));
    records.push_back(compare_scaled("thesis_vs_newton_max_difference", compare_algorithms(context, problem).difference,
                                     0.0, 1.0, 1e-4));
    tag(records, first, "flat-punch", {{"beta", number_text(t.beta)}});
  }
  // Frictionless stiff punch on a large support: P / (pi sqrt(a^2 - x^2)) within 3 % for
  // |x| < 0.8a, with linear and with quadratic elements.
  const auto half_plane = load_contact_example(context, "contact_punch_halfplane.toml");
  const double a = half_plane.parameters.at("a"), P = half_plane.parameters.at("P");
  const reference::FlatPunchPlane exact{P, a, 1.0};
  for (Interpolation interpolation : {Interpolation::linear, Interpolation::quadratic}) {
    auto problem = half_plane.problem;
    problem.mesh.interpolation = interpolation;
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    const double worst = flat_punch_max_error(result.pairs, exact);
    const std::size_t first = records.size();
    records.push_back(compare_scaled("pressure_max_relative_error", worst, 0.0, 1.0, 0.03));
    tag(records, first, "flat-punch",
        {{"interpolation", to_string(interpolation)}, {"support", "half-plane"}, {"beta", "0"}});
  }
  return records;
}

}  // namespace

// The Hertz ball's a, p0 (fitted), delta within 2 % and its profile within 3 % of p0, for
// the problem of contact_hertz_sphere.toml (P and R from `file`) as modified by the caller.
void hertz_ball_records(const Context& context, const io::ContactFile& file, const contact::ContactProblem& problem,
                        std::vector<Record>& records) {
  const double R = file.parameters.at("R"), P = file.parameters.at("P");
  const auto hertz = reference::hertz_point_contact(P, R, problem.elastic(0).material,
                                                    std::numeric_limits<double>::infinity(), problem.elastic(1).material);
  const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
  records.push_back(compare_relative("a", result.summary.contact_radius, hertz.contact_radius(), 0.02));
  records.push_back(compare_relative("p0", fitted_p0(result.pairs, hertz.contact_radius()), hertz.max_pressure(), 0.02));
  records.push_back(report_only("p0_axis_node", result.summary.centre_pressure, hertz.max_pressure()));
  records.push_back(compare_relative("delta", -result.summary.approach, hertz.approach(), 0.02));
  double profile = 0.0;
  for (const auto& pair : result.pairs)
    if (pair.coordinate > 1e-12 && pair.coordinate < 0.9 * hertz.contact_radius())
      profile = std::max(profile, std::abs(-pair.p_n - hertz.pressure(pair.coordinate)) / hertz.max_pressure());
  records.push_back(compare_scaled("pressure_profile_max_error", profile, 0.0, 1.0, 0.03));
}

// Independently meshed contact zones (node-to-segment pairs, pairing.hpp): the ball with
// 30 elements on its zone, the support with 47 or 36 on its own (a body 1 much finer than
// body 2 gets a warning: pairing.hpp). Hertz (P = 31.5) and
// Spence (beta = 0.1) held to the matching-mesh tolerances: a, p0 (fitted), delta 2 %, the
// profile 3 % of p0; c/a within 0.03 of 0.513. The axis pair is reported: the projection
// puts it 4-5 % high (2 % with matching meshes).
std::vector<Record> run_non_matching(const Context& context) {
  std::vector<Record> records;
  for (const int support_elements : {47, 36}) {
    const io::ParameterOverrides overrides{{"contact_elements", 30}, {"contact_elements_2", support_elements}};
    auto hertz_file = load_contact_example(context, "contact_hertz_sphere.toml", overrides);
    auto problem = hertz_file.problem;
    problem.drop_interior_points();
    const std::size_t first = records.size();
    hertz_ball_records(context, hertz_file, problem, records);
    tag(records, first, "hertz-sphere", {{"P", number_text(hertz_file.parameters.at("P"))},
                                         {"contact_elements", "30/" + std::to_string(support_elements)}});
    auto spence_file = load_contact_example(context, "contact_spence_sphere.toml", overrides);
    spence_file.problem.drop_interior_points();
    spence_file.problem.set_friction(0.1);
    const auto spence = contact::solve_contact(with_operator(context, spence_file.problem), context.progress);
    const std::size_t second = records.size();
    records.push_back(compare_scaled("c_over_a", spence.summary.stick_ratio(), 0.513, 1.0, 0.03));
    tag(records, second, "spence-sphere",
        {{"beta", "0.1"}, {"contact_elements", "30/" + std::to_string(support_elements)}});
  }
  return records;
}

// Mortar pairing (pairing.hpp, pairing = "mortar") on the Hertz ball, 30 elements on the
// ball's zone (body 1) against 120 and 19 on the support's, linear and quadratic elements.
// Held to 1 % of p0: every pair's pressure inside 0.8a, the axis pair included, and the axis
// pair alone, for linear 30/120 (measured 0.58 %; node-to-segment 6.4 %) and quadratic
// 30/120 and 30/19 (0.07 % and 0.23 %; node-to-segment 17.7 % and 4.4 %). Linear 30/19 (body
// 1 the finer) keeps its oscillation under mortar (9.4 %, axis pair -4.1 %; node-to-segment
// 12.4 %): a, the axis pair and the profile are reported, not held (docs/contact.md,
// "Mortar pairing"). The fitted p0 is held to 2 % in every run.
std::vector<Record> run_mortar_pairing(const Context& context) {
  std::vector<Record> records;
  for (const Interpolation interpolation : {Interpolation::linear, Interpolation::quadratic})
    for (const int support_elements : {120, 19}) {
      const io::ParameterOverrides overrides{{"contact_elements", 30}, {"contact_elements_2", support_elements}};
      auto file = load_contact_example(context, "contact_hertz_sphere.toml", overrides);
      auto problem = file.problem;
      problem.drop_interior_points();
      problem.mesh.interpolation = interpolation;
      problem.contacts.front().pairing = contact::Pairing::mortar;
      const double R = file.parameters.at("R"), P = file.parameters.at("P");
      const auto hertz = reference::hertz_point_contact(P, R, problem.elastic(0).material,
                                                        std::numeric_limits<double>::infinity(),
                                                        problem.elastic(1).material);
      const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
      const double a = hertz.contact_radius(), p0 = hertz.max_pressure();
      double profile = 0.0;  // the axis pair included
      for (const auto& pair : result.pairs)
        if (std::abs(pair.coordinate) < 0.8 * a)
          profile = std::max(profile, std::abs(-pair.p_n - hertz.pressure(std::abs(pair.coordinate))) / p0);
      const std::size_t first = records.size();
      records.push_back(compare_relative("p0", fitted_p0(result.pairs, a), p0, 0.02));
      if (interpolation == Interpolation::quadratic || support_elements > 30) {
        records.push_back(compare_relative("a", result.summary.contact_radius, a, 0.02));
        records.push_back(compare_relative("p0_axis_node", result.summary.centre_pressure, p0, 0.01));
        records.push_back(compare_scaled("pressure_profile_max_error", profile, 0.0, 1.0, 0.01));
      } else {
        records.push_back(report_only("a", result.summary.contact_radius, a));
        records.push_back(report_only("p0_axis_node", result.summary.centre_pressure, p0));
        records.push_back(report_value("pressure_profile_max_error", profile));
      }
      tag(records, first, "hertz-sphere",
          {{"pairing", "mortar"},
           {"interpolation", interpolation == Interpolation::linear ? "linear" : "quadratic"},
           {"contact_elements", "30/" + std::to_string(support_elements)}});
    }
  return records;
}

// Interface pressure of a shrink fit (shaft of radii a, b in a hub of radii b, c, radial
// interference delta, frictionless) against Lame for free ends:
//   p = delta / { b [ (1/E_o)((c^2 + b^2)/(c^2 - b^2) + nu_o) + (1/E_i)((b^2 + a^2)/(b^2 - a^2) - nu_i) ] },
// with E / (1 - nu^2) and nu / (1 - nu) in plane strain.
double shrink_fit_pressure(double a, double b, double c, double delta, const Material& shaft, const Material& hub,
                           AnalysisType type) {
  auto effective = [type](const Material& m) {
    if (type != AnalysisType::plane_strain) return m;
    const double nu = m.poisson_ratio;
    return Material{m.young_modulus / (1.0 - nu * nu), nu / (1.0 - nu)};
  };
  const Material i = effective(shaft), o = effective(hub);
  const double hub_term = ((c * c + b * b) / (c * c - b * b) + o.poisson_ratio) / o.young_modulus;
  const double shaft_term = ((b * b + a * a) / (b * b - a * a) - i.poisson_ratio) / i.young_modulus;
  return delta / (b * (hub_term + shaft_term));
}

// Shrink fit (examples/contact_shrink_fit*.toml): the interference declared on the
// contact, the pressure of every pair within 0.5 % of Lame in plane stress and plane strain
// (quarter model); in axisymmetry, long tubes with free ends, the mean pressure over the
// first wall thickness from the mid-plane (the open-ended state, plane-stress formula).
std::vector<Record> run_shrink_fit(const Context& context) {
  std::vector<Record> records;
  for (const AnalysisType type : {AnalysisType::plane_stress, AnalysisType::plane_strain, AnalysisType::axisymmetric}) {
    const bool axisymmetric = type == AnalysisType::axisymmetric;
    auto file = load_contact_example(context, axisymmetric ? "contact_shrink_fit_axisymmetric.toml" : "contact_shrink_fit.toml");
    auto problem = file.problem;
    problem.analysis = type;
    const double a = file.parameters.at("a"), b = file.parameters.at("b"), c = file.parameters.at("c");
    const double expected = shrink_fit_pressure(a, b, c, file.parameters.at("delta"), problem.elastic(0).material,
                                                problem.elastic(1).material,
                                                axisymmetric ? AnalysisType::plane_stress : type);
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    double worst = 0.0, sum = 0.0;
    int count = 0;
    for (const auto& pair : result.pairs) {
      if (axisymmetric && pair.position.y() > b - a) continue;
      worst = std::max(worst, std::abs(-pair.p_n / expected - 1.0));
      sum += -pair.p_n;
      ++count;
    }
    const std::size_t first = records.size();
    records.push_back(compare_relative("interface_pressure", sum / count, expected, 5e-3));
    if (!axisymmetric) records.push_back(compare_scaled("pressure_max_deviation", worst, 0.0, 1.0, 5e-3));
    tag(records, first, "shrink-fit", {{"analysis", to_string(type)}});
  }
  return records;
}

// Quadratic elements in contact (both zones, every boundary): the Hertz ball (a, p0, delta
// within 2 %, the profile 3 % of p0), Spence's c/a (beta = 0.1) within 0.03 of 0.513, and the
// plane-strain cylinder half model (every pair within 1 % for |x| <= 0.8a).
std::vector<Record> run_contact_quadratic(const Context& context) {
  std::vector<Record> records;
  auto hertz_file = load_contact_example(context, "contact_hertz_sphere.toml");
  auto problem = hertz_file.problem;
  problem.drop_interior_points();
  problem.mesh.interpolation = Interpolation::quadratic;
  std::size_t first = records.size();
  hertz_ball_records(context, hertz_file, problem, records);
  tag(records, first, "hertz-sphere", {{"interpolation", "quadratic"}, {"P", number_text(hertz_file.parameters.at("P"))}});

  auto spence_file = load_contact_example(context, "contact_spence_sphere.toml");
  auto spence = spence_file.problem;
  spence.drop_interior_points();
  spence.mesh.interpolation = Interpolation::quadratic;
  spence.set_friction(0.1);
  first = records.size();
  records.push_back(
      compare_scaled("c_over_a", contact::solve_contact(with_operator(context, spence), context.progress).summary.stick_ratio(), 0.513, 1.0, 0.03));
  tag(records, first, "spence-sphere", {{"interpolation", "quadratic"}, {"beta", "0.1"}});

  auto half_file = load_contact_example(context, "contact_hertz_cylinder_half.toml");
  auto half = half_file.problem;
  half.drop_interior_points();
  half.mesh.interpolation = Interpolation::quadratic;
  const reference::HertzLineContact line{half_file.parameters.at("P"), half_file.parameters.at("R"),
                                         reference::contact_modulus(half.elastic(0).material, half.elastic(1).material,
                                                                    half.analysis)};
  const auto half_result = contact::solve_contact(with_operator(context, half), context.progress);
  double worst = 0.0;
  for (const auto& pair : half_result.pairs)
    if (pair.coordinate <= 0.8 * line.half_width())
      worst = std::max(worst, std::abs(-pair.p_n / line.pressure(pair.coordinate) - 1.0));
  first = records.size();
  records.push_back(compare_scaled("max_pressure_error", worst, 0.0, 1.0, 0.01));
  tag(records, first, "hertz-cylinder-half", {{"interpolation", "quadratic"}, {"contact_elements", "25"}});
  return records;
}

// Cylinder on a block in plane strain, half model with coarse symmetry lines
// (examples/contact_hertz_cylinder_half.toml): every pair's pressure for |x| <= 0.8a within
// 1 % of 2D Hertz at that x, for 25, 50 and 100 contact elements. The corner transition
// grades the symmetry lines toward the contact zone; measured 0.24, 0.27, 0.41 % (without
// it the pair next to the symmetry line is off by +202, +340, +587 %).
std::vector<Record> run_hertz_cylinder_half(const Context& context) {
  std::vector<Record> records;
  for (int elements : {25, 50, 100}) {
    const auto file = load_contact_example(context, "contact_hertz_cylinder_half.toml", {{"contact_elements", elements}});
    const auto& problem = file.problem;
    // The half model carries P/2 of the cylinder's load P per unit length.
    const double P = file.parameters.at("P"), R = file.parameters.at("R");
    const reference::HertzLineContact hertz{
        P, R, reference::contact_modulus(problem.elastic(0).material, problem.elastic(1).material, problem.analysis)};
    const double a = hertz.half_width();
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    double worst = 0.0;
    for (const auto& pair : result.pairs)
      if (pair.coordinate <= 0.8 * a)
        worst = std::max(worst, std::abs(-pair.p_n / hertz.pressure(pair.coordinate) - 1.0));
    const std::size_t first = records.size();
    records.push_back(compare_scaled("max_pressure_error", worst, 0.0, 1.0, 0.01));
    records.push_back(report_only("a", result.summary.contact_radius, a));  // edge resolved to one element
    tag(records, first, "hertz-cylinder-half", {{"contact_elements", std::to_string(elements)}});
  }
  return records;
}

// The ball examples' a and p0 (fitted) at load P against Hertz, within 1 %.
void add_ball_against_hertz(const io::ContactFile& file, double P, const contact::ContactResult& result,
                            std::vector<Record>& records) {
  const auto& problem = file.problem;
  const auto hertz = reference::hertz_point_contact(P, file.parameters.at("R"), problem.elastic(0).material,
                                                    std::numeric_limits<double>::infinity(), problem.elastic(1).material);
  records.push_back(compare_relative("a", result.summary.contact_radius, hertz.contact_radius(), 0.01));
  records.push_back(compare_relative("p0", fitted_p0(result.pairs, hertz.contact_radius()), hertz.max_pressure(), 0.01));
}

// The README's ball at P = 400, where Hertz's a = 0.163 outgrows the example's zones (r <=
// 0.1): the run stops with the clipped-zone error (contact/zone_ends.hpp) instead of a
// punch-like answer (a = 0.099, -39 %; centre pressure +30 %). With zones to r = 0.2 (60
// elements each, the same element size) a and p0 land within 1 % of Hertz.
std::vector<Record> run_clipped_zone(const Context& context) {
  std::vector<Record> records;
  const double P = 400.0;
  const auto clipped = load_contact_example(context, "contact_hertz_sphere.toml", {{"P", P}});
  std::string message;
  try {
    contact::solve_contact(with_operator(context, clipped.problem), context.progress);
  } catch (const SolverError& error) {
    message = error.what();
  }
  const bool refused = message.find("is clipped by its zone") != std::string::npos &&
                       message.find("boundary 'contact' of body 'ball'") != std::string::npos;
  records.push_back(require_at_least("example_zone_refused", refused ? 1.0 : 0.0, 1.0));
  const auto file = load_contact_example(context, "contact_hertz_sphere.toml",
                                         {{"P", P}, {"rc", 0.2}, {"contact_elements", 60}});
  const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
  add_ball_against_hertz(file, P, result, records);
  tag(records, 0, "clipped-zone", {{"P", number_text(P)}});
  return records;
}

// Contact zones found from candidate surfaces (contact_resolution = 0.02; the candidates are
// whole boundaries meshed with 16 elements, no element counts on a zone): the ball of
// examples/contact_hertz_sphere_adaptive.toml at P = 31.5 and 400, and the half cylinder of
// examples/contact_hertz_cylinder_adaptive.toml at P = 66.15 and 20 times that, each from
// its one file: a and p0 within 1 % of Hertz. The 1 %: the edge is located to a fraction of
// the pair spacing (0.02 a), and at P = 400 (a/R = 0.16) the ball's curvature and the
// support's finite size stand between the model and Hertz's half-spaces (declared zones of
// 60 elements to r = 0.2 give -0.40 %: validate clipped-zone). Each run ends resolved: the
// pair spacing at the edge at most 0.02 of the width.
std::vector<Record> run_zone_growth(const Context& context) {
  std::vector<Record> records;
  const auto resolved = [&](const contact::ContactResult& result) {
    const auto& last = result.zone.passes.back();
    records.push_back(require_at_least("resolved", last.resolved && last.edge_spacing <= 0.02 * last.width ? 1.0 : 0.0, 1.0));
    records.push_back(report_value("passes", static_cast<double>(result.zone.passes.size())));
    records.push_back(report_value("pairs", static_cast<double>(last.pairs)));
  };
  for (const double P : {31.5, 400.0}) {
    const std::size_t first = records.size();
    auto file = load_contact_example(context, "contact_hertz_sphere_adaptive.toml", {{"P", P}});
    file.problem.drop_interior_points();
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    add_ball_against_hertz(file, P, result, records);
    resolved(result);
    tag(records, first, "zone-growth", {{"body", "ball"}, {"P", number_text(P)}});
  }
  for (const double P : {66.15, 20 * 66.15}) {
    const std::size_t first = records.size();
    auto file = load_contact_example(context, "contact_hertz_cylinder_adaptive.toml", {{"P", P}});
    file.problem.drop_interior_points();
    const auto& problem = file.problem;
    const reference::HertzLineContact hertz{
        P, file.parameters.at("R"),
        reference::contact_modulus(problem.elastic(0).material, problem.elastic(1).material, problem.analysis)};
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    records.push_back(compare_relative("a", result.summary.contact_radius, hertz.half_width(), 0.01));
    records.push_back(compare_relative("p0", result.summary.centre_pressure, hertz.max_pressure(), 0.01));
    resolved(result);
    tag(records, first, "zone-growth", {{"body", "cylinder"}, {"P", number_text(P)}});
  }
  return records;
}

// The half model under refinement of its contact zones (examples/contact_hertz_cylinder_half.toml,
// symmetry lines): the centre pressure within 0.3 % of 2D Hertz at N = 50, 200, 800 contact
// elements, and converging: each fourfold refinement changes it less than the one before
// (measured +0.033, +0.056, +0.064 %, then +0.064 % at 1 600 and 3 200). Written with
// roller lines (u1 = 0, t2 = 0) the same model drifted without bound: +0.27, +0.58, +1.07 %
// (docs/corners.md). The limit is Hertz's, not the model's: Hertz takes the cylinder as a
// half-plane with a parabolic gap, which leaves an error of order (a/R)^2. So at N = 800 the
// load times 4 (a/R 0.07 -> 0.14, the zone rc twice as wide, the same pairs per a) must
// multiply the error by 4 (within [3, 5]; measured 3.81). A block 2 and 4 times as large
// moved it by -0.002 %, the far boundaries meshed 2 and 4 times as finely by +0.001 and
// -0.004 % (docs/corners.md): neither is the limit.
std::vector<Record> run_hertz_cylinder_half_refinement(const Context& context) {
  std::vector<Record> records;
  // The centre pressure and 2D Hertz's, and the example's P and rc.
  struct Run {
    double centre, hertz, P, rc;
    double error() const { return centre / hertz - 1.0; }
  };
  const auto run = [&](const io::ParameterOverrides& overrides) {
    auto file = load_contact_example(context, "contact_hertz_cylinder_half.toml", overrides);
    auto& problem = file.problem;
    problem.drop_interior_points();
    const double P = file.parameters.at("P"), R = file.parameters.at("R");
    const reference::HertzLineContact hertz{
        P, R, reference::contact_modulus(problem.elastic(0).material, problem.elastic(1).material, problem.analysis)};
    const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
    return Run{result.summary.centre_pressure, hertz.max_pressure(), P, file.parameters.at("rc")};
  };
  std::vector<Run> runs;
  for (const int elements : {50, 200, 800}) {
    runs.push_back(run({{"contact_elements", elements}}));
    const std::size_t first = records.size();
    records.push_back(compare_relative("centre_pressure", runs.back().centre, runs.back().hertz, 3e-3));
    tag(records, first, "hertz-cylinder-half-refinement", {{"contact_elements", std::to_string(elements)}});
  }
  const std::size_t first = records.size();
  records.push_back(require_at_least("convergence_change_shrinks",
                                     std::abs(runs[1].error() - runs[0].error()) - std::abs(runs[2].error() - runs[1].error()),
                                     0.0));
  tag(records, first, "hertz-cylinder-half-refinement", {{"contact_elements", "50 -> 200 -> 800"}});
  const Run wider = run({{"contact_elements", 800}, {"P", 4.0 * runs[2].P}, {"rc", 2.0 * runs[2].rc}});
  const std::size_t at = records.size();
  records.push_back(compare_scaled("error_ratio_at_twice_a_over_R", wider.error() / runs[2].error(), 4.0, 1.0, 1.0));
  tag(records, at, "hertz-cylinder-half-refinement", {{"contact_elements", "800"}, {"P", "4 P"}});
  return records;
}

std::vector<Case> contact_cases() {
  return {
      {"hertz-sphere", "V.5.2.3", "ball on a flat support, frictionless, against Hertz and Huber", run_hertz_sphere},
      {"spence-sphere", "V.5.2.4", "ball on a flat support with friction, stick zone against Spence", run_spence_sphere},
      {"spence-halfspace", "Annex E", "Spence's half-space setting: independent ring-kernel model, same solver",
       run_spence_halfspace},
      {"non-matching-zones", "V.2.2", "Hertz and Spence balls with 30 elements on the ball's zone and 47 or 36 on the support's",
       run_non_matching},
      {"mortar-pairing", "-",
       "Hertz ball with mortar pairing: 30 elements on the ball's zone against 120 and 19 on the support's, linear and quadratic",
       run_mortar_pairing},
      {"shrink-fit", "-", "shaft in a hub with radial interference, frictionless: interface pressure against Lame",
       run_shrink_fit},
      {"contact-quadratic", "V.5.2", "Hertz, Spence and the cylinder half model with quadratic elements",
       run_contact_quadratic},
      {"hertz-cylinder-half", "-", "cylinder on a block, plane-strain half model with coarse symmetry lines, 2D Hertz",
       run_hertz_cylinder_half},
      {"flat-punch", "V.5.1", "stiff flat punch: thesis' bilateral case and a rigid punch on a half-plane", run_flat_punch},
      {"hertz-cylinder-half-refinement", "-",
       "the half model's centre pressure converges as its contact zones are refined (symmetry lines)",
       run_hertz_cylinder_half_refinement},
      {"clipped-zone", "-", "a contact outgrowing its zone is refused; zones long enough give Hertz", run_clipped_zone},
      {"zone-growth", "-", "contact zones found from candidate surfaces: Hertz ball and cylinder, loads 13 and 20 apart",
       run_zone_growth},
  };
}

}  // namespace bemcontact::validation
