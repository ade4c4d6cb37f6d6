#include "bemcontact/contact/indentation.hpp"

#include <cmath>
#include <limits>

namespace bemcontact::contact {

std::optional<IndentationReport> indentation_report(const ContactProblem& problem, const ContactResult& result) {
  if (problem.analysis != AnalysisType::axisymmetric || problem.contacts.size() != 1 || result.steps.empty() ||
      result.records.size() != result.steps.size())
    return std::nullopt;
  const auto& contact = problem.contacts.front();
  const auto& ball = problem.bodies[static_cast<std::size_t>(contact.side2.body)];
  if (!ball.rigid || ball.rigid->profile != "sphere") return std::nullopt;
  double radius = 0.0;
  for (const auto& piece : ball.rigid->contour)
    if (piece.shape == geometry::PieceShape::arc) radius = (piece.start - piece.center).norm();
  // The ball's depth per step: its prescribed displacement, or the approach of a force load on it.
  int force = -1;
  for (std::size_t k = 0; k < problem.forces.size(); ++k)
    if (problem.forces[k].body == contact.side2.body && problem.forces[k].component == 1) force = static_cast<int>(k);
  if (radius <= 0.0 || (force < 0 && !ball.rigid->displacement)) return std::nullopt;
  IndentationReport out;
  out.ball_diameter = 2.0 * radius;
  for (std::size_t s = 0; s < result.steps.size(); ++s) {
    const auto& record = result.records[s];
    const double depth = force >= 0 ? -record.motions[force]
                                    : -ball.rigid->displacement->y() * ball.rigid->amplitude.at(record.load_time);
    out.times.push_back(record.time);
    out.depths.push_back(depth);
    out.loads.push_back(result.steps[s].normal_force);
    if (result.steps[s].normal_force > out.peak_load) {
      out.peak_step = static_cast<int>(s);
      out.peak_load = result.steps[s].normal_force;
      out.peak_depth = depth;
      out.contact_radius = result.steps[s].contact_radius;
    }
  }
  const double P = out.peak_load, a = out.contact_radius, D = out.ball_diameter, d = 2.0 * a;
  if (a > 0.0) out.meyer = P / (M_PI * a * a);
  out.brinell = d < D ? 2.0 * P / (M_PI * D * (D - std::sqrt(D * D - d * d))) : std::numeric_limits<double>::quiet_NaN();
  const std::size_t k = static_cast<std::size_t>(out.peak_step);
  if (k + 1 < out.depths.size() && out.depths[k + 1] < out.depths[k])
    out.unloading_stiffness = (out.loads[k] - out.loads[k + 1]) / (out.depths[k] - out.depths[k + 1]);
  // The body: its region (regions are numbered body by body) and its contact node on the axis.
  std::size_t region = 0;
  for (int b = 0; b < contact.side1.body; ++b) region += problem.bodies[static_cast<std::size_t>(b)].regions.size();
  region += static_cast<std::size_t>(contact.side1.region);
  const auto& material = problem.bodies[static_cast<std::size_t>(contact.side1.body)]
                             .regions[static_cast<std::size_t>(contact.side1.region)]
                             .body.material;
  // Sneddon's is for a homogeneous body: none for one of several regions (a coating).
  if (problem.bodies[static_cast<std::size_t>(contact.side1.body)].regions.size() == 1)
    out.elastic_unloading_stiffness =
        2.0 * material.young_modulus / (1.0 - material.poisson_ratio * material.poisson_ratio) * a;
  if (region < result.meshes.size()) {
    const auto& mesh = result.meshes[region];
    double closest = std::numeric_limits<double>::infinity();
    for (const int piece : contact.side1.pieces)
      for (const Index node : mesh.piece_nodes[static_cast<std::size_t>(piece)]) {
        const double r = std::abs(mesh.nodes[static_cast<std::size_t>(node)].position.x());
        if (r < closest)
          closest = r, out.residual_depth = -result.boundary[region].displacement[static_cast<std::size_t>(node)].y();
      }
  }
  return out;
}

}  // namespace bemcontact::contact
