// Plane reference cases of chapter II (II.7.1-II.7.3) and a plane-strain Lame tube.
#include <cmath>
#include <map>
#include <numbers>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/reference/cantilever.hpp"
#include "bemcontact/reference/curved_beam.hpp"
#include "bemcontact/reference/kirsch.hpp"
#include "bemcontact/reference/lame.hpp"
#include "bemcontact/reference/uniaxial_tension.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/case_support.hpp"
#include "bemcontact/validation/plane_cases.hpp"

namespace bemcontact::validation {
namespace {


double max_abs_difference(const Mat2& a, const Mat2& b) { return (a - b).cwiseAbs().maxCoeff(); }

Mat2 in_plane(const bem::StressTensor& s) {
  Mat2 m;
  m << s.s11, s.s12, s.s12, s.s22;
  return m;
}


}  // namespace

// Plate in uniaxial tension (II.7.1). Linear and quadratic elements reproduce the linear
// field exactly (straight boundary), so the tolerance is round-off: 1e-10.
// Constant elements approximate u by a piecewise constant: first order, O(h). The
// thesis reports < 0.5 % on u and < 1 % on p with 16 constant elements; we measure 2.2 %
// there (max norm over the nodes), so the thesis' bounds are checked on refined meshes
// (4, 16 and 64 elements per side), with the observed order, and the traction error in the
// rms norm (at the element next to a corner the max-norm traction error of constant
// elements does not decrease with h).
std::vector<Record> run_plate_tension(const Context& context) {
  std::vector<Record> records;
  const auto file = load_example(context, "plate_tension.toml");
  auto problem = file.problem;
  const double P = file.parameters.at("P");
  const reference::PlateInTension exact{P, problem.body.material, AnalysisType::plane_stress};
  struct Errors { double u_max, p_rms, s_max, ui_max, si_max; };
  auto measure = [&](Interpolation interpolation, int per_side) {
    auto p = problem;
    p.mesh.interpolation = interpolation;
    for (auto& piece : p.body.pieces) piece.elements = per_side;
    const auto result = bem::solve_body(with_operator(context, p), context.progress);
    Errors e{0, 0, 0, 0, 0};
    double u_scale = 0.0, p_sum = 0.0, p_ref = 0.0;
    for (Index i = 0; i < result.mesh.node_count(); ++i) {
      const auto& node = result.mesh.nodes[i];
      const Vec2 u = exact.displacement(node.position);
      const Vec2 t = exact.stress(node.position).traction(node.normal);
      u_scale = std::max(u_scale, u.norm());
      e.u_max = std::max(e.u_max, (result.boundary.displacement[i] - u).norm());
      p_sum += (result.boundary.traction[i] - t).squaredNorm();
      p_ref += t.squaredNorm();
      e.s_max = std::max(e.s_max, max_abs_difference(in_plane(result.boundary.stress[i]),
                                                     exact.stress(node.position).in_plane()) / P);
    }
    e.u_max /= u_scale;
    e.p_rms = std::sqrt(p_sum / p_ref);
    for (std::size_t k = 0; k < result.interior.points.size(); ++k) {
      const Vec2& x = result.interior.points[k];
      e.ui_max = std::max(e.ui_max, (result.interior.displacement[k] - exact.displacement(x)).norm() / u_scale);
      e.si_max = std::max(e.si_max, max_abs_difference(in_plane(result.interior.stress[k]), exact.stress(x).in_plane()) / P);
    }
    return e;
  };
  // Linear and quadratic elements hold the linear field exactly (quadratic: Gauss
  // quadrature to ~1e-15): round-off.
  for (Interpolation interpolation : {Interpolation::linear, Interpolation::quadratic}) {
    const auto exact_field = measure(interpolation, 4);
    const std::size_t first = records.size();
    records.push_back(compare_scaled("u_boundary_max_error", exact_field.u_max, 0.0, 1.0, 1e-10));
    records.push_back(compare_scaled("p_boundary_rms_error", exact_field.p_rms, 0.0, 1.0, 1e-10));
    records.push_back(compare_scaled("s_boundary_max_error", exact_field.s_max, 0.0, 1.0, 1e-10));
    records.push_back(compare_scaled("u_interior_max_error", exact_field.ui_max, 0.0, 1.0, 1e-10));
    records.push_back(compare_scaled("s_interior_max_error", exact_field.si_max, 0.0, 1.0, 1e-10));
    tag(records, first, "plate-tension", {{"interpolation", to_string(interpolation)}, {"elements", "16"}});
  }
  Errors previous{};
  for (int per_side : {4, 16, 64}) {
    const auto e = measure(Interpolation::constant, per_side);
    const std::size_t first = records.size();
    if (per_side == 64) {
      records.push_back(compare_scaled("u_boundary_max_error", e.u_max, 0.0, 1.0, 5e-3));
      records.push_back(compare_scaled("p_boundary_rms_error", e.p_rms, 0.0, 1.0, 1e-2));
    } else {
      // Coarser meshes: reported, and bounded by the first-order error estimate from the
      // finest mesh (error ~ C h): u_max(64) * 64 / n with a factor 2 for pre-asymptotic.
      records.push_back(compare_scaled("u_boundary_max_error", e.u_max, 0.0, 1.0, 2.0 * 0.002 * 64.0 / per_side));
      records.push_back(compare_scaled("p_boundary_rms_error", e.p_rms, 0.0, 1.0, 2.0 * 0.004 * std::sqrt(64.0 / per_side)));
    }
    if (per_side > 4) {
      records.push_back(require_at_least("order_u_boundary", observed_order(previous.u_max, e.u_max, 4.0), 0.8));
    }
    previous = e;
    tag(records, first, "plate-tension",
        {{"interpolation", "constant"}, {"elements", std::to_string(4 * per_side)}});
  }
  return records;
}

// The closed form of examples/cantilever.toml (its L, H and material).
reference::CantileverParabolicShear cantilever_reference(const io::ProblemFile& file) {
  reference::CantileverParabolicShear exact;
  exact.length = file.parameters.at("L");
  exact.height = file.parameters.at("H");
  exact.material = file.problem.body.material;
  return exact;
}

// Cantilever with parabolic end shear (II.7.2), meshes M1 (h = L/2) to M5 (h = L/32).
// Tolerances: no worse than the thesis' own error on each mesh (Table II.4, with half a
// unit of its last printed digit), and the 1 % at M5.
std::vector<Record> run_cantilever(const Context& context) {
  std::vector<Record> records;
  const auto file = load_example(context, "cantilever.toml");
  const double L = file.parameters.at("L"), H = file.parameters.at("H");
  const auto exact = cantilever_reference(file);
  const Vec2 B(L, H / 2), C(0, H / 2), O(0, 0);
  const double u1_B = exact.displacement(B).x(), u2_B = exact.displacement(B).y();
  const double s11_C = exact.stress(C).s11, s12_O = exact.stress(O).s12;
  // Thesis Table II.4 values per mesh: u1(B), u2(B), s11(C), s12(O).
  const double thesis[5][4] = {{-1.50, 3.50, -3.16, 1.25}, {-1.80, 4.11, -3.51, 1.13},
                               {-1.93, 4.37, -3.74, 1.06}, {-1.97, 4.46, -3.86, 1.03},
                               {-1.99, 4.48, -3.92, 1.01}};
  const double refs[4] = {u1_B, u2_B, s11_C, s12_O};
  const char* names[4] = {"u1_B", "u2_B", "s11_C", "s12_O"};
  struct Elements {
    Interpolation interpolation;
    bool discontinuous;
  };
  for (const Elements kind : {Elements{Interpolation::linear, false}, Elements{Interpolation::linear, true},
                              Elements{Interpolation::quadratic, false}}) {
    auto problem = file.problem;
    problem.mesh.interpolation = kind.interpolation;
    if (kind.discontinuous) geometry::use_discontinuous_elements(problem.mesh);
    const std::string order_name = to_string(kind.interpolation);
    const std::string continuity = kind.discontinuous ? "discontinuous" : "continuous";
    double errors[5][4] = {};
    double stress_errors[5] = {};
    for (int m = 0; m < 5; ++m) {
      const double h = L / std::pow(2.0, m + 1);
      for (auto& piece : problem.body.pieces)
        piece.elements = std::max(1, static_cast<int>(std::lround(geometry::piece_length(piece) / h)));
      const auto result = bem::solve_body(with_operator(context, problem), context.progress);
      const Vec2 uB = bem::vector_at_vertex(result.mesh, vertex_at(result.mesh, B), result.boundary.displacement);
      const auto sC = bem::stress_at_vertex(result.mesh, problem.body, problem.analysis, vertex_at(result.mesh, C), result.boundary.stress);
      const auto sO = bem::stress_at_vertex(result.mesh, problem.body, problem.analysis, vertex_at(result.mesh, O), result.boundary.stress);
      const double computed[4] = {uB.x(), uB.y(), sC.s11, sO.s12};
      // Nodal boundary stresses over the whole boundary, relative to the peak |s11| = 4.
      double s_max = 0.0;
      for (Index i = 0; i < result.mesh.node_count(); ++i)
        s_max = std::max(s_max, max_abs_difference(in_plane(result.boundary.stress[i]),
                                                   exact.stress(result.mesh.nodes[i].position).in_plane()));
      stress_errors[m] = s_max / std::abs(s11_C);
      const std::size_t first = records.size();
      for (int q = 0; q < 4; ++q) {
        const double thesis_error = std::abs(thesis[m][q] - refs[q]) / std::abs(refs[q]) + 0.005 / std::abs(refs[q]);
        const double tolerance = m == 4 ? std::min(0.01, thesis_error) : thesis_error;
        records.push_back(compare_relative(names[q], computed[q], refs[q], tolerance));
        errors[m][q] = records.back().error;
      }
      // First order near the corners (one-sided derivatives at shifted nodes): bounded by
      // the thesis' own stress error at C on that mesh.
      records.push_back(compare_scaled("s_boundary_max_error", stress_errors[m], 0.0, 1.0,
                                       std::abs(thesis[m][2] - s11_C) / std::abs(s11_C) + 0.005));
      tag(records, first, "cantilever",
          {{"interpolation", order_name}, {"continuity", continuity}, {"mesh", "M" + std::to_string(m + 1)},
           {"h", "L/" + std::to_string(1 << (m + 1))}, {"elements", std::to_string(result.mesh.element_count())}});
    }
    // Observed orders. Continuous linear elements: second order is nominal for the
    // displacements; we measure 1.55 / 1.57 between M4 and M5 (near a corner the error
    // grows like h^2 r^-0.45 toward it, docs/corners.md), so 1.4 is required; boundary
    // stresses first order (0.8). Discontinuous linear elements (nodes at the Gauss points)
    // reach second order: 1.9 is required over M3-M5 (one fit over both refinements),
    // 1.85 per step. Quadratic elements: third order for the displacements (2.8 required,
    // M3-M4 and M4-M5), second for the boundary stresses (from the tangential strain of
    // three neighbouring nodes; 1.8). The corner stresses s11(C) and s12(O) follow from
    // the prescribed tractions alone (stress_at_vertex): no order.
    const bool quadratic = kind.interpolation == Interpolation::quadratic;
    const double u_order = quadratic ? 2.8 : kind.discontinuous ? 1.85 : 1.4;
    if (kind.discontinuous) {
      const std::size_t from = records.size();
      for (int q = 0; q < 2; ++q)
        records.push_back(require_at_least(std::string("order_") + names[q], observed_order(errors[2][q], errors[4][q], 4.0), 1.9));
      tag(records, from, "cantilever", {{"interpolation", order_name}, {"continuity", continuity}, {"mesh", "M3-M5"}});
    }
    for (int m = quadratic || kind.discontinuous ? 2 : 3; m < 4; ++m) {
      const std::size_t from = records.size();
      for (int q = 0; q < 2; ++q) {
        // An error at round-off on both meshes has no order (quadratic elements give u1(B)
        // to 1e-15): then the error itself is held to 1e-9.
        if (errors[m][q] < 1e-9)
          records.push_back(compare_scaled(std::string(names[q]) + "_error", errors[m + 1][q], 0.0, 1.0, 1e-9));
        else
          records.push_back(require_at_least(std::string("order_") + names[q],
                                             observed_order(errors[m][q], errors[m + 1][q], 2.0), u_order));
      }
      records.push_back(require_at_least("order_s_boundary", observed_order(stress_errors[m], stress_errors[m + 1], 2.0),
                                         quadratic ? 1.8 : 0.8));
      tag(records, from, "cantilever",
          {{"interpolation", order_name}, {"continuity", continuity},
           {"mesh", "M" + std::to_string(m + 1) + "-M" + std::to_string(m + 2)}});
    }
  }
  return records;
}

// One side of a corner refined alone (issue: "accurate at every corner"). The cantilever
// of II.7.2 with its end x = 0 clamped by the exact displacement (a smooth polynomial
// field), 16 elements per H/2; the axis OA is refined by 1, 4 and 16, so its elements
// meet the clamped end (at O) and the loaded end (at A) with those size ratios. Quantity:
// the largest nodal stress error (relative to max |s11| = 4) over the nodes within one
// coarse element of O and A. With the corner transition the coarse sides are graded toward
// the fine one and the error must stay within 1.5x the uniform mesh's; without it
// (reported) it grows with the ratio.
std::vector<Record> run_corner_refinement(const Context& context) {
  std::vector<Record> records;
  const auto file = load_example(context, "cantilever.toml");
  const double L = file.parameters.at("L"), H = file.parameters.at("H");
  const auto exact = cantilever_reference(file);
  auto base = file.problem;
  const int per_half_height = 16;
  const double h = 0.5 * H / per_half_height;
  for (std::size_t k = 0; k < base.body.pieces.size(); ++k) {
    auto& piece = base.body.pieces[k];
    piece.elements = std::max(1, static_cast<int>(std::lround(geometry::piece_length(piece) / h)));
    if (piece.name == "CO") {  // clamped by the exact field: no point constraints needed
      auto& bc = base.body.conditions[k];
      bc.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
      bc.value = {[exact](const Vec2& x) { return exact.displacement(x).x(); },
                  [exact](const Vec2& x) { return exact.displacement(x).y(); }};
      bc.signature = "exact displacement";
    }
  }
  base.body.constraints.clear();
  base.interior_points.clear();
  const Vec2 O(0, 0), A(L, 0);
  auto corner_error = [&](int ratio, double transition) {
    auto problem = base;
    problem.mesh.corner_transition = transition;
    for (auto& piece : problem.body.pieces)
      if (piece.name == "OA") piece.elements *= ratio;
    const auto result = bem::solve_body(with_operator(context, problem), context.progress);
    double worst = 0.0;
    for (Index i = 0; i < result.mesh.node_count(); ++i) {
      const Vec2& x = result.mesh.nodes[i].position;
      if ((x - O).norm() > 1.001 * h && (x - A).norm() > 1.001 * h) continue;
      worst = std::max(worst, max_abs_difference(in_plane(result.boundary.stress[i]), exact.stress(x).in_plane()));
    }
    return worst / 4.0;
  };
  const double uniform = corner_error(1, base.mesh.corner_transition);
  for (int ratio : {1, 4, 16}) {
    const std::size_t first = records.size();
    const double error = ratio == 1 ? uniform : corner_error(ratio, base.mesh.corner_transition);
    records.push_back(compare_scaled("max_corner_error", error, 0.0, 1.0, 1.5 * uniform));
    if (ratio > 1) records.push_back(report_only("max_corner_error_without_transition", corner_error(ratio, 0.0), uniform));
    tag(records, first, "corner-refinement", {{"ratio", std::to_string(ratio)}});
  }
  return records;
}

// Curved bar under end couples [TimoshenkoGoodier1970, §29], examples/curved_beam.toml:
// s_tt at every boundary node within 1 % of the peak |s_tt| with linear elements. The
// worst node is the one next to an inner corner, where the error of linear elements is
// first order (5.6, 2.6, 1.2, 0.61 % for n = 8, 16, 32, 64): n = 64 is their mesh for the
// 1 %; quadratic elements meet it from n = 4.
std::vector<Record> run_curved_beam(const Context& context) {
  std::vector<Record> records;
  const auto file = load_example(context, "curved_beam.toml");
  reference::CurvedBeamEndCouple exact;
  exact.inner_radius = file.parameters.at("a");
  exact.outer_radius = file.parameters.at("b");
  exact.moment = file.parameters.at("M");
  exact.material = file.problem.body.material;
  exact.type = file.problem.analysis;
  const double peak = std::max(std::abs(exact.polar_stress(exact.inner_radius).tt),
                               std::abs(exact.polar_stress(exact.outer_radius).tt));
  struct Variant { Interpolation interpolation; int n; double tolerance; };
  // Linear: 1 % at n = 64; n = 16 held to the first-order bound 4 %. Quadratic: 1 % at
  // n = 4 (measured 0.68 %), and its displacement order from n = 4 to 8 to 16 (3.66, 3.51).
  double previous_u = 0.0;
  for (const Variant v : {Variant{Interpolation::linear, 16, 0.04}, Variant{Interpolation::linear, 64, 0.01},
                          Variant{Interpolation::quadratic, 4, 0.01}, Variant{Interpolation::quadratic, 8, 0.01},
                          Variant{Interpolation::quadratic, 16, 0.01}}) {
    const int n = v.n;
    auto problem = file.problem;
    problem.mesh.interpolation = v.interpolation;
    const std::map<std::string, int> per_n{{"end0", 1}, {"outer", 4}, {"end90", 1}, {"inner", 2}};
    for (auto& piece : problem.body.pieces) piece.elements = per_n.at(piece.name) * n;
    const auto result = bem::solve_body(with_operator(context, problem), context.progress);
    double worst = 0.0, u_error = 0.0, u_scale = 0.0;
    for (Index i = 0; i < result.mesh.node_count(); ++i) {
      const Vec2& x = result.mesh.nodes[i].position;
      const Vec2 e_theta = Vec2(-x.y(), x.x()).normalized();
      const double computed = e_theta.dot(in_plane(result.boundary.stress[i]) * e_theta);
      worst = std::max(worst, std::abs(computed - exact.polar_stress(x.norm()).tt) / peak);
      u_error = std::max(u_error, (result.boundary.displacement[i] - exact.displacement(x)).norm());
      u_scale = std::max(u_scale, exact.displacement(x).norm());
    }
    const std::size_t first = records.size();
    records.push_back(compare_scaled("max_stt_error", worst, 0.0, 1.0, v.tolerance));
    const bool quadratic = v.interpolation == Interpolation::quadratic;
    if (quadratic && previous_u > 0.0)
      records.push_back(require_at_least("order_u_boundary", observed_order(previous_u, u_error / u_scale, 2.0), 2.8));
    previous_u = quadratic ? u_error / u_scale : 0.0;
    tag(records, first, "curved-beam",
        {{"interpolation", to_string(v.interpolation)}, {"n", std::to_string(n)},
         {"elements", std::to_string(result.mesh.element_count())}});
  }
  return records;
}

// Plate with a hole (II.7.3) against Kirsch. The plate half-width is 20 a, so the
// finite-width effect on the hole stresses is ~0.3 %; tolerances: the 2 % on
// s_tt at theta = 90 deg (from the load axis) and 1 % of P on s_rr, s_rt.
std::vector<Record> run_plate_hole(const Context& context) {
  const auto file = load_example(context, "plate_hole.toml");
  auto problem = file.problem;
  const double P = file.parameters.at("P"), a = file.parameters.at("a");
  problem.interior_points.clear();
  problem.operator_choice.kind = bem::OperatorKind::dense;
  const auto kirsch_checks = [&](const bem::BodyResult& result,
                                 std::vector<Record>& records) {
    const auto sA = bem::stress_at_vertex(result.mesh, problem.body, problem.analysis, vertex_at(result.mesh, Vec2(a, 0)), result.boundary.stress);
    records.push_back(compare_relative("stt_hole_90", sA.s22, 3.0 * P, 0.02));
    double srr_max = 0.0, srt_max = 0.0, stt_error = 0.0;
    reference::KirschPlate kirsch;
    kirsch.hole_radius = a;
    kirsch.applied_stress = P;
    kirsch.material = problem.body.material;
    int hole_piece = -1;
    for (std::size_t p = 0; p < problem.body.pieces.size(); ++p)
      if (problem.body.pieces[p].name == "hole") hole_piece = static_cast<int>(p);
    const auto& hole_nodes = result.mesh.piece_nodes.at(hole_piece);
    for (std::size_t k = 0; k < hole_nodes.size(); ++k) {
      const Index i = hole_nodes[k];
      const Vec2 x = result.mesh.nodes[i].position;
      // The shifted corner nodes and their neighbours carry the first-order corner error
      // (1-2.5 % of 3P here, for corner shifts 0.1-0.4); they are covered by stt_hole_90.
      const bool corner_node = k < 2 || k + 2 >= hole_nodes.size();
      const double theta = std::atan2(x.y(), x.x());
      const Vec2 er(std::cos(theta), std::sin(theta)), et(-std::sin(theta), std::cos(theta));
      const Mat2 s = in_plane(result.boundary.stress[i]);
      srr_max = std::max(srr_max, std::abs(er.dot(s * er)));
      srt_max = std::max(srt_max, std::abs(er.dot(s * et)));
      const auto exact = kirsch.polar_stress(x.norm(), theta);
      if (!corner_node) stt_error = std::max(stt_error, std::abs(et.dot(s * et) - exact.tt));
    }
    records.push_back(compare_scaled("srr_hole_max", srr_max, 0.0, P, 0.01));
    records.push_back(compare_scaled("srt_hole_max", srt_max, 0.0, P, 0.01));
    records.push_back(compare_scaled("stt_hole_max_error", stt_error, 0.0, 3.0 * P, 0.01));
  };
  auto records = for_each_interpolation("plate-hole", problem, [&](const bem::ProblemDefinition& variant, std::vector<Record>& out) {
    const auto result = bem::solve_body(with_operator(context, variant), context.progress);
    kirsch_checks(result, out);
    return result.mesh.element_count();
  });
  // The same on hierarchical matrices (default accuracy 1e-10), linear elements refined 4
  // times (600 unknowns; far blocks compressed): the Kirsch checks, and the boundary
  // solution against the dense one within 1e-6 (measured u 4e-9, t 3e-8).
  bem::ProblemDefinition fine = problem;
  for (auto& piece : fine.body.pieces) piece.elements *= 4;
  const auto dense = bem::solve_body(with_operator(context, fine), context.progress);
  fine.operator_choice.kind = bem::OperatorKind::compressed;
  const auto compressed = bem::solve_body(with_operator(context, fine), context.progress);
  const std::size_t first = records.size();
  kirsch_checks(compressed, records);
  double du = 0.0, dp = 0.0, u_scale = 0.0, p_scale = 0.0;
  for (Index i = 0; i < dense.mesh.node_count(); ++i) {
    du = std::max(du, (compressed.boundary.displacement[i] - dense.boundary.displacement[i]).norm());
    dp = std::max(dp, (compressed.boundary.traction[i] - dense.boundary.traction[i]).norm());
    u_scale = std::max(u_scale, dense.boundary.displacement[i].norm());
    p_scale = std::max(p_scale, dense.boundary.traction[i].norm());
  }
  records.push_back(compare_scaled("u_against_dense", du, 0.0, u_scale, 1e-6));
  records.push_back(compare_scaled("t_against_dense", dp, 0.0, p_scale, 1e-6));
  tag(records, first, "plate-hole",
      {{"interpolation", "linear"}, {"operator", "compressed"}, {"elements", std::to_string(compressed.mesh.element_count())}});
  return records;
}

// Thick tube under internal pressure in plane strain (Lame), quarter model with arcs.
// Error of linear elements on chords: O(h^2); with 32 elements per quarter arc the
// chord sag alone is 0.12 % of the radius, so the tolerance is 0.5 %.
std::vector<Record> run_thick_ring_plane_strain(const Context& context) {
  const auto file = load_example(context, "thick_ring_plane_strain.toml");
  auto problem = file.problem;
  const double a = file.parameters.at("a"), b = file.parameters.at("b"), p = file.parameters.at("p");
  const reference::ThickCylinder exact{a, b, p, 0.0, problem.body.material, reference::CylinderEnds::plane_strain};
  return for_each_interpolation("thick-ring-plane-strain", problem, [&](const bem::ProblemDefinition& variant, std::vector<Record>& records) {
    const auto result = bem::solve_body(with_operator(context, variant), context.progress);
    const double c = std::sqrt(0.5);
    const Index ia = node_at(result.mesh, Vec2(a * c, a * c)), ib = node_at(result.mesh, Vec2(b * c, b * c));
    const Vec2 er(c, c), et(-c, c);
    records.push_back(compare_relative("ur_a", result.boundary.displacement[ia].dot(er), exact.radial_displacement(a), 5e-3));
    records.push_back(compare_relative("ur_b", result.boundary.displacement[ib].dot(er), exact.radial_displacement(b), 5e-3));
    records.push_back(compare_relative("stt_a", et.dot(in_plane(result.boundary.stress[ia]) * et), exact.polar_stress(a).tt, 5e-3));
    records.push_back(compare_relative("stt_b", et.dot(in_plane(result.boundary.stress[ib]) * et), exact.polar_stress(b).tt, 5e-3));
    // s_zz = nu (s_rr + s_tt) is a small difference of large terms: compare against p.
    records.push_back(compare_scaled("szz_a", result.boundary.stress[ia].s33, exact.polar_stress(a).zz, p, 5e-3));
    double s_error = 0.0;
    for (std::size_t k = 0; k < result.interior.points.size(); ++k) {
      const Vec2& x = result.interior.points[k];
      s_error = std::max(s_error, max_abs_difference(in_plane(result.interior.stress[k]), exact.stress(x).in_plane()));
    }
    records.push_back(compare_scaled("s_interior_max_error", s_error, 0.0, p, 5e-3));
    return result.mesh.element_count();
  });
}

}  // namespace bemcontact::validation

namespace bemcontact::validation {

std::vector<Case> plane_cases() {
  return {
      {"plate-tension", "II.7.1", "plate in uniaxial tension, linear and constant elements", run_plate_tension},
      {"cantilever", "II.7.2", "cantilever with parabolic end shear, meshes M1-M5", run_cantilever},
      {"plate-hole", "II.7.3", "plate with a circular hole against Kirsch", run_plate_hole},
      {"thick-ring-plane-strain", "-", "thick tube under internal pressure, plane strain (Lame)",
       run_thick_ring_plane_strain},
      {"corner-refinement", "II.4.4.2", "one side of a corner refined 1, 4, 16 times: corner error bounded",
       run_corner_refinement},
      {"curved-beam", "-", "curved bar under end couples (Timoshenko & Goodier 29): s_tt at every node",
       run_curved_beam},
  };
}

}  // namespace bemcontact::validation
