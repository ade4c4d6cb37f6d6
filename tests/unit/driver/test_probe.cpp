// `bemcontact probe` (driver/probe.hpp): values at new points of a finished run, from its
// files alone, against the run's own interior points, closed forms (Lame, Hertz-Huber, the
// compound ring), the whole body of a half model,
// elastoplastic runs (their cells' fields), and its refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <tuple>
#include <vector>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "bemcontact/core/error.hpp"
#include "bemcontact/driver/probe.hpp"
#include "bemcontact/driver/run.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"
#include "bemcontact/io/output/run_summary.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "bemcontact/reference/lame.hpp"
#include "bemcontact/reference/two_layer_ring.hpp"
#include "support/example_text.hpp"

namespace bemcontact::driver {
namespace {

using test_support::example_text;
using test_support::replaced;

// A run's folder in memory, as the command line finds it on disk.
struct RunFiles {
  std::map<std::string, std::string> files;
  FileReader reader() const {
    return [this](const std::string& name) -> std::optional<std::string> {
      const auto found = files.find(name);
      if (found == files.end()) return std::nullopt;
      return found->second;
    };
  }
};

RunFiles run(const std::string& text, const std::string& file_name) {
  RunFiles folder;
  const auto output = run_problem(text, file_name, {});
  for (const auto& file : output.files.files()) folder.files[file.name] = file.content;
  return folder;
}

ProbeRequest lines(const std::vector<io::ProbeLine>& lines) {
  ProbeRequest request;
  request.lines = lines;
  return request;
}

ProbeRequest listed(const std::vector<Vec2>& points) {
  ProbeRequest request;
  request.points_file = "points.csv";
  for (std::size_t k = 0; k < points.size(); ++k) request.listed.push_back({points[k], static_cast<int>(k) + 1});
  return request;
}

// One row of probe.csv.
struct Row {
  Index point = 0;
  int line = 0;
  double distance = 0.0;
  Vec2 position;
  std::string body;
  bool on_boundary = false;
  Vec2 u;
  bem::StressTensor s;
};

std::vector<Row> rows_of(const ProbeOutput& output) {
  std::vector<Row> rows;
  for (const auto& file : output.files.files()) {
    if (file.name != "probe.csv") continue;
    std::istringstream in(file.content);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "point,line,distance,x,y,body,on_boundary,u1,u2,s11,s22,s12,s33,von_mises,s1,s2,s3");
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream fields(line);
      for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
      EXPECT_EQ(f.size(), 17u) << line;
      const auto d = [&](int k) { return std::stod(f.at(k)); };
      rows.push_back({std::stol(f[0]), std::stoi(f[1]), d(2), Vec2(d(3), d(4)), f[5], f[6] == "1", Vec2(d(7), d(8)),
                      {d(9), d(10), d(11), d(12)}});
    }
  }
  return rows;
}

std::vector<Row> probe(const RunFiles& folder, const ProbeRequest& request) {
  return rows_of(probe_run(folder.reader(), request, {}));
}

// The message of the InputError `action` throws ("" when it throws none).
template <class Action>
std::string input_error(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

// The run's own interior points and the probe's at the same places go through the same
// Somigliana integrals on the same mesh and boundary values (boundary.csv holds them at
// full precision): equal to round-off, near the hole (the near-boundary blend) included.
TEST(Probe, PointsOfPlateHoleEqualTheRunsInteriorPoints) {
  const std::vector<Vec2> points{{1.01 * std::cos(0.3), 1.01 * std::sin(0.3)}, {1.05, 0.02}, {0.3, 1.2},
                                 {2.0, 2.0}, {4.5, 0.7}, {0.02, 3.0}, {19.0, 19.0}};
  std::string listed_text = "points = [";
  for (const auto& p : points) listed_text += "[" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + "], ";
  listed_text += "]\n";
  // The same positions as the run reads them (to_string rounds to 6 decimals).
  std::vector<Vec2> asked;
  for (const auto& p : points) asked.emplace_back(std::stod(std::to_string(p.x())), std::stod(std::to_string(p.y())));
  const std::string text = replaced(example_text("plate_hole.toml"),
                                    "grid = { x = [0.0, 5.0, 26], y = [0.0, 5.0, 26] }", listed_text);
  const auto folder = run(text, "plate_hole.toml");
  const auto rows = probe(folder, listed(asked));

  std::istringstream interior(folder.files.at("interior.csv"));
  std::string line;
  std::getline(interior, line);
  ASSERT_EQ(rows.size(), points.size());
  double scale = 0.0, difference = 0.0;
  for (const auto& row : rows) {
    ASSERT_TRUE(std::getline(interior, line));
    std::vector<double> v;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) v.push_back(std::stod(field));
    EXPECT_EQ(row.position, Vec2(v[1], v[2]));
    EXPECT_EQ(row.body, "body");
    EXPECT_FALSE(row.on_boundary);
    const std::array<double, 6> run_values{v[3], v[4], v[5], v[6], v[7], v[8]};
    const std::array<double, 6> probe_values{row.u.x(), row.u.y(), row.s.s11, row.s.s22, row.s.s12, row.s.s33};
    for (int k = 0; k < 6; ++k) {
      scale = std::max(scale, std::abs(run_values[k]));
      difference = std::max(difference, std::abs(run_values[k] - probe_values[k]) / (k < 2 ? 1e-4 : 2.5));
    }
  }
  // Relative to the scales u ~ 1e-4, sigma ~ P = 2.5: round-off only.
  EXPECT_LT(difference, 1e-12);
}

// A line through the wall of the thick cylinder (axisymmetric, free ends), ends on the
// bore and the outer surface, against Lame: the run's own discretisation error (validate
// thick-cylinder holds u_r on the surfaces to 0.1 %; measured here 0.092 % at worst, the
// stresses 0.31 % of P at worst, s_tt at the bore).
TEST(Probe, LineThroughTheThickCylinderMatchesLame) {
  const auto folder = run(example_text("thick_cylinder.toml"), "thick_cylinder.toml");
  const auto rows = probe(folder, lines({{Vec2(45.0, 20.0), Vec2(90.0, 20.0), 19}}));
  const double P = 10.0;
  Material material;
  material.young_modulus = 1.0;
  material.poisson_ratio = 0.25;
  const reference::ThickCylinder exact{45.0, 90.0, P, 0.0, material, reference::CylinderEnds::open};
  ASSERT_EQ(rows.size(), 19u);
  double u_error = 0.0, s_error = 0.0;
  for (const auto& row : rows) {
    const double r = row.position.x();
    const auto s = exact.polar_stress(r);
    EXPECT_EQ(row.on_boundary, r == 45.0 || r == 90.0) << r;
    EXPECT_NEAR(row.distance, r - 45.0, 1e-12);
    u_error = std::max(u_error, std::abs(row.u.x() / exact.radial_displacement(r) - 1.0));
    s_error = std::max({s_error, std::abs(row.s.s11 - s.rr), std::abs(row.s.s33 - s.tt), std::abs(row.s.s22),
                        std::abs(row.s.s12)});
  }
  EXPECT_LT(u_error, 1e-3);
  EXPECT_LT(s_error, 5e-3 * P);

  // The wall's linearised stresses (probe.json): membrane hoop and radial stresses, Lame's
  // averages A +- B/(ab), and the hoop bending 6B/t^2 (c t/(ab) - ln(b/a)), c the mid-radius;
  // integrals of the pointwise values, so within their bound (measured 0.094 % of P).
  const auto output = probe_run(folder.reader(), lines({{Vec2(45.0, 20.0), Vec2(90.0, 20.0), 19}}), {});
  nlohmann::json probe_summary;
  for (const auto& file : output.files.files())
    if (file.name == "probe.json") probe_summary = nlohmann::json::parse(file.content);
  const auto& linearised = probe_summary["lines"][0]["linearised"];
  const double a = 45.0, b = 90.0, t = b - a, A = P * a * a / (b * b - a * a), B = P * a * a * b * b / (b * b - a * a);
  EXPECT_NEAR(linearised["membrane"]["s33"].get<double>(), A + B / (a * b), 5e-3 * P);
  EXPECT_NEAR(linearised["membrane"]["along"].get<double>(), A - B / (a * b), 5e-3 * P);
  EXPECT_NEAR(linearised["membrane"]["across"].get<double>(), 0.0, 5e-3 * P);
  EXPECT_NEAR(linearised["bending"]["s33"].get<double>(), 6.0 * B / (t * t) * (0.5 * (a + b) * t / (a * b) - std::log(b / a)),
              5e-3 * P);
}

// The Hertz ball's support along the axis, from the contact's centre down to 2a, at the
// end of the load history: Huber's axis stresses within 0.5 % of p0 (measured 0.05 %;
// validate hertz-sphere holds the run's own grid beside the axis to 3 %), the maximum
// shear's value within 3 % (measured 0.02 %) and its depth within the sampling step a/8.
// The centre is on both bodies' boundaries: a row for each, both with s_zz near -p0 (the
// axis pair is a few per cent high by collocation: validate's 2 %; measured 0.03 %).
TEST(Probe, HertzSupportAlongTheAxisMatchesHuber) {
  const std::string text = example_text("contact_hertz_sphere.toml");
  const auto folder = run(text, "contact_hertz_sphere.toml");
  const auto file = io::parse_contact_problem(text, "contact_hertz_sphere.toml");
  const auto& support = file.problem.bodies[1].regions[0].body.material;
  const auto hertz = reference::hertz_point_contact(file.parameters.at("P"), file.parameters.at("R"),
                                                    file.problem.bodies[0].regions[0].body.material,
                                                    std::numeric_limits<double>::infinity(), support);
  const double a = hertz.contact_radius(), p0 = hertz.max_pressure(), nu = support.poisson_ratio;
  const auto rows = probe(folder, lines({{Vec2(0.0, 0.0), Vec2(0.0, -2.0 * a), 17}}));
  ASSERT_EQ(rows.size(), 18u);  // the centre twice
  EXPECT_EQ(rows[0].body, "ball");
  EXPECT_EQ(rows[1].body, "support");
  EXPECT_TRUE(rows[0].on_boundary && rows[1].on_boundary);
  EXPECT_NEAR(rows[0].s.s22, -p0, 0.02 * p0);
  EXPECT_NEAR(rows[1].s.s22, -p0, 0.02 * p0);
  double error = 0.0, tau_max = 0.0, tau_depth = 0.0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const auto& row = rows[k];
    EXPECT_EQ(row.body, "support");
    const double depth = -row.position.y();
    const auto exact = hertz.axis_stress(nu, depth);
    error = std::max({error, std::abs(row.s.s11 - exact.s11), std::abs(row.s.s22 - exact.s22),
                      std::abs(row.s.s33 - exact.s33)});
    const double tau = 0.5 * std::abs(row.s.s11 - row.s.s22);
    if (tau > tau_max) tau_max = tau, tau_depth = depth;
  }
  EXPECT_LT(error, 0.005 * p0);
  const auto huber = reference::huber_max_shear_on_axis(nu);
  EXPECT_NEAR(tau_max / p0, huber.shear_over_p0, 0.03 * huber.shear_over_p0);
  EXPECT_NEAR(tau_depth / a, huber.depth_over_a, 0.0625 + 1e-12);
}

// The compound ring (decomposition file, two layers, 24 linear elements per quarter arc)
// along a ray at 40 degrees, between nodes: the bore end lies inside the liner's chords
// (near-boundary blend), the outer end outside the tube's chords but on the true circle
// (on the boundary), and the interface point belongs to both layers, each with its own
// hoop stress. Against the closed form within validate dd-two-layer-ring's bounds, the
// discretisation error of the arcs' chords (1 % on u, 2 % of p on stresses; measured 0.27 %
// and 0.79 %).
TEST(Probe, RayThroughTheCompoundRingMatchesTheClosedFormInEachLayer) {
  const std::string text = example_text("dd_two_layer_ring.toml");
  const auto folder = run(text, "dd_two_layer_ring.toml");
  reference::TwoLayerRing exact;
  exact.inner_radius = 1.0;
  exact.interface_radius = 1.5;
  exact.outer_radius = 2.0;
  exact.inner_pressure = 100.0;
  exact.inner = {200000.0, 0.3};
  exact.outer = {70000.0, 0.33};
  const Vec2 direction(std::cos(40.0 * M_PI / 180.0), std::sin(40.0 * M_PI / 180.0));
  const auto rows = probe(folder, lines({{direction, 2.0 * direction, 21}}));
  ASSERT_EQ(rows.size(), 22u);  // the interface point in both layers
  EXPECT_TRUE(rows.back().on_boundary);
  EXPECT_EQ(rows.back().body, "tube");
  double u_error = 0.0, s_error = 0.0, u_scale = exact.displacement(direction).norm();
  int at_interface = 0;
  for (const auto& row : rows) {
    const double r = row.position.norm();
    const bool interface = std::abs(r - 1.5) < 1e-12;
    at_interface += interface;
    EXPECT_EQ(row.body, r < 1.5 - 1e-12 || (interface && at_interface == 1) ? "liner" : "tube") << r;
    // The layer's own closed form at the interface.
    const Vec2 x = interface ? row.position * (row.body == "liner" ? 1.0 - 1e-12 : 1.0 + 1e-12) : row.position;
    const auto e = exact.stress(x);
    u_error = std::max(u_error, (row.u - exact.displacement(x)).norm());
    s_error = std::max({s_error, std::abs(row.s.s11 - e.s11), std::abs(row.s.s22 - e.s22),
                        std::abs(row.s.s12 - e.s12), std::abs(row.s.s33 - e.s33)});
  }
  EXPECT_EQ(at_interface, 2);
  EXPECT_LT(u_error / u_scale, 1e-2);
  EXPECT_LT(s_error, 2e-2 * exact.inner_pressure);

  // Walked from outside in, the interface's rows come in the order crossed (tube, then
  // liner), and the section's linearisation is the same with the bending reversed.
  const auto linearised = [&](const io::ProbeLine& line) {
    const auto output = probe_run(folder.reader(), lines({line}), {});
    for (const auto& file : output.files.files())
      if (file.name == "probe.json") return nlohmann::json::parse(file.content)["lines"][0]["linearised"];
    return nlohmann::json();
  };
  const io::ProbeLine inward{2.0 * direction, direction, 21};
  const auto reversed = probe(folder, lines({inward}));
  ASSERT_EQ(reversed.size(), 22u);
  EXPECT_EQ(reversed[10].body, "tube");
  EXPECT_EQ(reversed[11].body, "liner");
  const auto out = linearised({direction, 2.0 * direction, 21}), in = linearised(inward);
  for (const char* component : {"along", "across", "s33"})
    EXPECT_NEAR(out["membrane"][component].get<double>(), in["membrane"][component].get<double>(), 1e-9) << component;
  for (const char* component : {"across", "s33"})
    EXPECT_NEAR(out["bending"][component].get<double>(), -in["bending"][component].get<double>(), 1e-9) << component;
}

// A square plate with a central hole: the quarter with two symmetry lines (three images),
// or the whole plate, meshed alike (tests/unit/bem/test_symmetry.cpp). Probed in every
// quadrant, near the hole, on the far edges and on the symmetry lines, the quarter gives
// the whole plate's values: a point of a mirrored quadrant is taken at its image and
// mapped back.
std::string holed_plate(bool quarter) {
  std::string text = "analysis = \"plane_stress\"\n[mesh]\ncontinuity = \"discontinuous\"\ncorner_transition = 0\n"
                     "[material]\nE = 1000.0\nnu = 0.25\n";
  const auto piece = [&](const std::string& name, const std::string& from, const std::string& to, int elements,
                         const std::string& extra) {
    text += "[[boundary]]\nname = \"" + name + "\"\nfrom = " + from + "\nto = " + to +
            (elements > 0 ? "\nelements = " + std::to_string(elements) : std::string()) + "\n" + extra;
  };
  const std::string arc = "shape = \"arc\"\ncenter = [0.0, 0.0]\ndirection = \"cw\"\n";
  if (quarter) {
    piece("AB", "[1.0, 0.0]", "[4.0, 0.0]", 0, "symmetry = true\n");
    piece("BC", "[4.0, 0.0]", "[4.0, 4.0]", 5, "");
    piece("CD", "[4.0, 4.0]", "[0.0, 4.0]", 5, "t2 = \"1 + 0.1 * x^2\"\n");
    piece("DE", "[0.0, 4.0]", "[0.0, 1.0]", 0, "symmetry = true\n");
    piece("hole", "[0.0, 1.0]", "[1.0, 0.0]", 4, arc);
    return text;
  }
  piece("bottom", "[-4.0, -4.0]", "[4.0, -4.0]", 10, "t2 = \"-(1 + 0.1 * x^2)\"\n");
  piece("right", "[4.0, -4.0]", "[4.0, 4.0]", 10, "");
  piece("top", "[4.0, 4.0]", "[-4.0, 4.0]", 10, "t2 = \"1 + 0.1 * x^2\"\n");
  piece("left", "[-4.0, 4.0]", "[-4.0, -4.0]", 10, "");
  piece("hole1", "[0.0, 1.0]", "[1.0, 0.0]", 4, arc);
  piece("hole2", "[1.0, 0.0]", "[0.0, -1.0]", 4, arc);
  piece("hole3", "[0.0, -1.0]", "[-1.0, 0.0]", 4, arc);
  piece("hole4", "[-1.0, 0.0]", "[0.0, 1.0]", 4, arc);
  text += "[[constraint]]\nat = [0.0, 4.0]\nu1 = 0.0\n[[constraint]]\nat = [0.0, -4.0]\nu1 = 0.0\n"
          "[[constraint]]\nat = [4.0, 0.0]\nu2 = 0.0\n";
  return text;
}

TEST(Probe, AQuarterWithTwoSymmetryLinesGivesTheWholePlatesValues) {
  const auto quarter = run(holed_plate(true), "quarter.toml"), whole = run(holed_plate(false), "whole.toml");
  const double near = 1.03;  // inside the hole's first half element: the near-boundary blend
  const std::vector<Vec2> points{{1.5, 0.5},   {-1.5, 0.5},  {-1.5, -0.5}, {1.5, -0.5}, {0.3, -2.0},
                                 {-near * std::cos(0.4), -near * std::sin(0.4)},
                                 {-4.0, -1.3}, {2.5, -4.0},  {2.0, 0.0},   {0.0, -2.5}, {-3.0, 0.0}};
  const auto a = probe(quarter, listed(points)), b = probe(whole, listed(points));
  ASSERT_EQ(a.size(), points.size());
  ASSERT_EQ(b.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(a[k].on_boundary, b[k].on_boundary) << k;
    EXPECT_LT((a[k].u - b[k].u).norm(), 1e-12) << k;
    EXPECT_NEAR(a[k].s.s11, b[k].s.s11, 1e-9) << k;
    EXPECT_NEAR(a[k].s.s22, b[k].s.s22, 1e-9) << k;
    EXPECT_NEAR(a[k].s.s12, b[k].s.s12, 1e-9) << k;
  }
  EXPECT_TRUE(a[6].on_boundary);
  EXPECT_TRUE(a[7].on_boundary);
}

// --set values are replayed from summary.json's evaluated parameters: the mesh made again
// is the run's (here a finer contact zone), so the probe accepts it.
TEST(Probe, ARunWithOverriddenParametersIsMeshedWithThem) {
  RunOptions options;
  io::add_parameter_override(options.overrides, "contact_elements=20");
  const auto output = run_problem(example_text("contact_hertz_sphere.toml"), "contact_hertz_sphere.toml", options);
  RunFiles folder;
  for (const auto& file : output.files.files()) folder.files[file.name] = file.content;
  const auto rows = probe(folder, lines({{Vec2(0.0, -0.01), Vec2(0.0, -0.1), 4}}));
  EXPECT_EQ(rows.size(), 4u);
}

// An adaptive contact zone: the probe meshes the run again with the zone's final meshes
// (summary.json: results.contacts[0].zone); without them the node check would refuse the
// run. The support's surface stress on the axis is -p0 (Hertz, 2 %).
TEST(Probe, AnAdaptiveZoneIsMeshedAsTheRunEndedIt) {
  const std::string text = example_text("contact_hertz_sphere_adaptive.toml");
  const auto folder = run(text, "contact_hertz_sphere_adaptive.toml");
  const auto file = io::parse_contact_problem(text, "contact_hertz_sphere_adaptive.toml");
  const auto hertz = reference::hertz_point_contact(file.parameters.at("P"), file.parameters.at("R"),
                                                    file.problem.bodies[0].regions[0].body.material,
                                                    std::numeric_limits<double>::infinity(),
                                                    file.problem.bodies[1].regions[0].body.material);
  const auto rows = probe(folder, lines({{Vec2(0.0, 0.0), Vec2(0.0, -0.1), 4}}));
  ASSERT_EQ(rows.size(), 5u);  // the centre in both bodies
  EXPECT_EQ(rows[1].body, "support");
  EXPECT_NEAR(rows[1].s.s22, -hertz.max_pressure(), 0.02 * hertz.max_pressure());
}

// A line that crosses the hole: its points in the hole are left out and named in a
// warning and in probe.json; the VTK polyline is broken there.
TEST(Probe, PointsOfALineInsideNoBodyAreLeftOutAndReported) {
  const auto folder = run(example_text("plate_tension.toml"), "plate_tension.toml");
  // The plate is [-1, 1] x [0, 2]: the line runs from outside, through it and out again.
  const auto output = probe_run(folder.reader(), lines({{Vec2(-2.0, 1.0), Vec2(2.0, 1.0), 9}}), {});
  const auto rows = rows_of(output);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows.front().point, 2);
  EXPECT_TRUE(rows.front().on_boundary);
  ASSERT_EQ(output.warnings.size(), 1u);
  EXPECT_NE(output.warnings[0].find("line 1: 4 of its 9 points are inside no body and left out: (-2, 1), (-1.5, 1),"), std::string::npos)
      << output.warnings[0];
  for (const auto& file : output.files.files())
    if (file.name == "probe.json") {
      const auto json = nlohmann::json::parse(file.content);
      EXPECT_EQ(json["outside"].size(), 4u);
      EXPECT_EQ(json["lines"][0]["outside"], 4);
      EXPECT_EQ(json["rows"], 5);
    }
}

// The rows of a run's interior table (x, y, u1, u2, s11, s22, s12, s33).
std::vector<std::array<double, 8>> interior_rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("point,x,y,u1,u2,s11,s22,s12,s33", 0), 0u) << line;
  std::vector<std::array<double, 8>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    std::array<double, 8> row{};
    for (int k = 0; k < 8; ++k) row[static_cast<std::size_t>(k)] = std::stod(f.at(static_cast<std::size_t>(k) + 1));
    rows.push_back(row);
  }
  return rows;
}

// An elastoplastic run, alone (the tube after unloading: residual stresses), in contact
// (the Brinell ball at its peak) or bonded to an elastic region (the tube of two rings,
// both regions' points): the probe makes the cells again, reads their plastic
// strains back from <body>_cells.csv (full precision) and adds their fields to Somigliana's
// of the boundary values, as the run does at its interior points: the same values to
// round-off. Without the cells the values are far off (the check that they count).
TEST(Probe, ElastoplasticRunsAloneOrInContactEqualTheRunsInteriorPoints) {
  const std::string tube =
      replaced(replaced(example_text("plastic_tube.toml"), "size = 0.08", "size = 0.32"), "increments = 20",
               "increments = 2");
  std::string ball = replaced(example_text("brinell.toml"), "cell = 0.16", "cell = 0.64");
  ball = replaced(replaced(ball, "end_time = 2.0", "end_time = 1.0"), "increments = 20", "increments = 2");
  ball = replaced(ball, "refine_size = \"cell / 4\"\n",
                  "refine_size = \"cell / 4\"\n[body.interior]\ngrid = { x = [0.05, 1.55, 4], y = [-1.55, -0.05, 4] }\n");
  // The tube of an elastoplastic inner ring bonded to an elastic outer one (no contact).
  const std::string bonded = replaced(replaced(example_text("plastic_tube_bonded.toml"), "cell = 0.08", "cell = 0.32"),
                                      "increments = 20", "increments = 4");
  struct Case {
    std::string text, name, cells;
    std::vector<std::string> interiors;
  };
  for (const auto& c : {Case{tube, "tube.toml", "tube_cells.csv", {"tube_interior.csv"}},
                        Case{ball, "brinell.toml", "block_cells.csv", {"block_interior.csv"}},
                        Case{bonded, "bonded.toml", "inner_ring_cells.csv",
                             {"inner_ring_interior.csv", "outer_ring_interior.csv"}}}) {
    auto folder = run(c.text, c.name);
    std::vector<std::array<double, 8>> expected;
    for (const auto& interior : c.interiors) {
      const auto rows = interior_rows(folder.files.at(interior));
      EXPECT_GE(rows.size(), 8u) << interior;
      expected.insert(expected.end(), rows.begin(), rows.end());
    }
    ASSERT_GE(expected.size(), 10u) << c.name;
    std::vector<Vec2> points;
    for (const auto& row : expected) points.emplace_back(row[0], row[1]);
    const auto rows = probe(folder, listed(points));
    ASSERT_EQ(rows.size(), expected.size()) << c.name;
    double largest = 0.0, off = 0.0, cells_part = 0.0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const auto& e = expected[k];
      largest = std::max({largest, std::abs(e[4]), std::abs(e[5]), std::abs(e[6]), std::abs(e[7])});
      const auto& s = rows[k].s;
      off = std::max({off, std::abs(s.s11 - e[4]), std::abs(s.s22 - e[5]), std::abs(s.s12 - e[6]),
                      std::abs(s.s33 - e[7])});
      EXPECT_NEAR(rows[k].u.x(), e[2], 1e-12 * std::abs(e[2]) + 1e-15) << c.name << " point " << k;
      EXPECT_NEAR(rows[k].u.y(), e[3], 1e-12 * std::abs(e[3]) + 1e-15) << c.name << " point " << k;
    }
    EXPECT_LE(off, 1e-10 * largest) << c.name;
    // The cells' plastic strains set to zero: Somigliana's of the boundary values alone.
    std::istringstream in(folder.files.at(c.cells));
    std::string line, zeroed;
    std::getline(in, line);
    zeroed = line + "\n";
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream fields(line);
      for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
      for (std::size_t k = 5; k <= 8; ++k) f[k] = "0";
      for (std::size_t k = 0; k < f.size(); ++k) zeroed += (k ? "," : "") + f[k];
      zeroed += "\n";
    }
    folder.files[c.cells] = zeroed;
    const auto elastic = probe(folder, listed(points));
    for (std::size_t k = 0; k < rows.size(); ++k)
      cells_part = std::max(cells_part, std::abs(elastic[k].s.s22 - rows[k].s.s22));
    EXPECT_GE(cells_part, 0.05 * largest) << c.name;
  }
}

// The cells' file missing or not matching the cells made again: refused with its name.
TEST(Probe, RefusesAnElastoplasticRunWithoutItsCells) {
  const std::string tube =
      replaced(replaced(example_text("plastic_tube.toml"), "size = 0.08", "size = 0.32"), "increments = 20",
               "increments = 2");
  auto folder = run(tube, "tube.toml");
  const auto request = lines({{Vec2(1.1, 0.1), Vec2(1.5, 0.1), 3}});
  const std::string cells = folder.files.at("tube_cells.csv");
  folder.files.erase("tube_cells.csv");
  EXPECT_NE(input_error([&] { probe_run(folder.reader(), request, {}); }).find("the run has no tube_cells.csv"),
            std::string::npos);
  folder.files["tube_cells.csv"] = cells.substr(0, cells.rfind('\n', cells.size() - 2) + 1);  // the last cell cut
  EXPECT_NE(input_error([&] { probe_run(folder.reader(), request, {}); }).find("cells stored"), std::string::npos);
}

TEST(Probe, RefusesWhatIsNotAFinishedRun) {
  const auto folder = run(example_text("plate_tension.toml"), "plate_tension.toml");
  const auto request = lines({{Vec2(-0.5, 1.0), Vec2(0.5, 1.0), 3}});
  ProbeOptions options;
  options.run_name = "out/plate";
  EXPECT_NE(input_error([&] { probe_run(RunFiles{}.reader(), request, options); })
                .find("out/plate: not the output folder of a run: it has no summary.json"),
            std::string::npos);
  RunFiles meshed;
  const auto mesh = mesh_problem(example_text("plate_tension.toml"), "plate_tension.toml", {});
  for (const auto& file : mesh.files.files()) meshed.files[file.name] = file.content;
  EXPECT_NE(input_error([&] { probe_run(meshed.reader(), request, options); }).find("`bemcontact mesh`"),
            std::string::npos);
  for (const char* damaged : {"{\"input\": 3, \"command\": \"run\"}", "[1]", "{\"input\": {\"sha256\": 5}}", "{"}) {
    auto broken = folder;
    broken.files["summary.json"] = damaged;
    EXPECT_NE(input_error([&] { probe_run(broken.reader(), request, options); })
                  .find("summary.json is not a run summary of bemcontact"),
              std::string::npos)
        << damaged;
  }
  auto unfinished = folder;
  unfinished.files.erase("boundary.csv");
  EXPECT_NE(input_error([&] { probe_run(unfinished.reader(), request, options); }).find("the run has no boundary.csv"),
            std::string::npos);
  EXPECT_NE(input_error([&] { probe_run(folder.reader(), ProbeRequest{}, options); }).find("give points"),
            std::string::npos);
  options.limits.max_interior_points = 2;
  EXPECT_NE(input_error([&] { probe_run(folder.reader(), request, options); }).find("raise it with --max-points"),
            std::string::npos);
}

// The solution belongs to the text the run read: a changed copy, a changed input file (for
// a folder without the copy) or a mesh that no longer matches the stored nodes is refused.
TEST(Probe, RefusesAProblemTextThatChangedSinceTheRun) {
  const std::string text = example_text("plate_tension.toml");
  const auto folder = run(text, "plate_tension.toml");
  const auto request = lines({{Vec2(-0.5, 1.0), Vec2(0.5, 1.0), 3}});
  auto tampered = folder;
  tampered.files["problem.toml"] = replaced(text, "P = 1.0", "P = 2.0");
  EXPECT_NE(input_error([&] { probe_run(tampered.reader(), request, {}); })
                .find("problem.toml was changed after the run: its SHA-256 is not summary.json's input.sha256"),
            std::string::npos);

  // A folder written before problem.toml existed: the input file, if unchanged, serves.
  auto older = folder;
  older.files.erase("problem.toml");
  ProbeOptions options;
  std::string input = text;
  options.read_input = [&](const std::string& path) -> std::optional<std::string> {
    EXPECT_NE(path.find("plate_tension.toml"), std::string::npos);
    return input;
  };
  EXPECT_EQ(rows_of(probe_run(older.reader(), request, options)).size(), 3u);
  input = replaced(text, "elements = 4", "elements = 5");
  EXPECT_NE(input_error([&] { probe_run(older.reader(), request, options); }).find("changed since the run"),
            std::string::npos);
  options.read_input = [](const std::string&) { return std::optional<std::string>(); };
  EXPECT_NE(input_error([&] { probe_run(older.reader(), request, options); }).find("cannot be read"),
            std::string::npos);

  // boundary.csv from another mesh (e.g. another version's mesher).
  auto stale = folder;
  auto& csv = stale.files["boundary.csv"];
  const auto x = csv.find(',', csv.find('\n')) + 1;  // node 0's x
  csv.replace(x, csv.find(',', x) - x, "-0.7");
  const auto stale_message = input_error([&] { probe_run(stale.reader(), request, {}); });
  EXPECT_NE(stale_message.find("does not match boundary.csv"),
            std::string::npos)
      << stale_message;
}

TEST(Probe, AListedPointInsideNoBodyIsAnErrorNamingItsLine) {
  const auto folder = run(example_text("plate_tension.toml"), "plate_tension.toml");
  const auto message = input_error([&] { probe_run(folder.reader(), listed({{0.0, 1.0}, {3.0, 1.0}, {5.0, 5.0}}), {}); });
  EXPECT_NE(message.find("points.csv:2: point (3, 1) lies inside no body (and 1 more points of the file)"),
            std::string::npos)
      << message;
  EXPECT_NE(input_error([&] { probe_run(folder.reader(), lines({{Vec2(3.0, 0.0), Vec2(3.0, 1.0), 3}}), {}); })
                .find("none of the 3 points lies inside a body"),
            std::string::npos);
}

}  // namespace
}  // namespace bemcontact::driver
