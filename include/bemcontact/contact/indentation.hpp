#pragma once
// The numbers of a ball indentation (docs/plasticity.md, "Brinell"): an axisymmetric
// contact between a body and a rigid sphere driven by a prescribed displacement or a force.
// From the history: the load-depth curve, the peak load P with its contact radius a, the
// Brinell hardness HB = 2P / (pi D (D - sqrt(D^2 - d^2))) from the impression's diameter
// d = 2a at the peak [Tabor1951], the Meyer hardness P / (pi a^2) (the mean pressure), the
// initial unloading stiffness against Sneddon's elastic 2 E* a [Sneddon1965] (an
// elastic unloading of a contact of radius a), and the dent's depth at the axis after the
// last step. Hardnesses in the file's stress unit (HB in kgf/mm^2 is the N/mm^2 value over
// 9.80665).
#include <optional>
#include <vector>

#include "bemcontact/contact/contact_solver.hpp"

namespace bemcontact::contact {

struct IndentationReport {
  double ball_diameter = 0.0;   // D
  std::vector<double> times, depths, loads;  // per step: the ball's depth below its start, the normal force
  int peak_step = 0;            // index of the largest load
  double peak_load = 0.0, peak_depth = 0.0, contact_radius = 0.0;  // P, h and a there
  double brinell = 0.0;         // HB (NaN when d >= D)
  double meyer = 0.0;           // P / (pi a^2)
  double unloading_stiffness = 0.0;          // (P_peak - P_next) / (h_peak - h_next); 0 without unloading
  // 2 E* a, E* = E / (1 - nu^2) of the body (rigid ball); 0 for a body of several regions
  // (a coating: no closed form)
  double elastic_unloading_stiffness = 0.0;
  double residual_depth = 0.0;  // -u_z of the body's contact node on the axis after the last step
};

// None unless the problem is an axisymmetric contact of one body with a rigid sphere moved
// along z by a displacement or a force load.
std::optional<IndentationReport> indentation_report(const ContactProblem& problem, const ContactResult& result);

}  // namespace bemcontact::contact
