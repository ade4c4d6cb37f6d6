#include "bemcontact/bem/postprocess.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "bemcontact/core/error.hpp"
#include "bemcontact/core/parallel.hpp"
#include "bemcontact/integration/plane_element.hpp"

namespace bemcontact::bem {
namespace {

Mat2 local_frame(const Vec2& normal) {
  Mat2 q;
  q << normal, Vec2(-normal.y(), normal.x());
  return q;
}

// Out-of-plane stress of a plane state.
double out_of_plane_stress(AnalysisType type, const Material& material, double s11, double s22) {
  return type == AnalysisType::plane_strain ? material.poisson_ratio * (s11 + s22) : 0.0;
}

}  // namespace

double StressTensor::von_mises() const {
  const double d12 = s11 - s22, d13 = s11 - s33, d23 = s22 - s33;
  return std::sqrt(0.5 * (d12 * d12 + d13 * d13 + d23 * d23) + 3.0 * s12 * s12);
}

std::array<double, 3> StressTensor::principal() const {
  const double mean = 0.5 * (s11 + s22), radius = std::hypot(0.5 * (s11 - s22), s12);
  std::array<double, 3> values{mean + radius, mean - radius, s33};
  std::sort(values.begin(), values.end(), std::greater<>());
  return values;
}

namespace {

bool stress_is_finite(const StressTensor& s) {
  return std::isfinite(s.s11) && std::isfinite(s.s22) && std::isfinite(s.s12) && std::isfinite(s.s33);
}

}  // namespace

std::vector<StressTensor> boundary_stresses(const geometry::BoundaryMesh& mesh, AnalysisType type,
                                            const Material& material,
                                            const BoundarySolution& solution,
                                            const std::vector<plasticity::Mandel>* plastic_strain) {
  const Index n = mesh.node_count();
  // Tangential strain e_ss = s . du/ds at each node, from the quadratic through the node
  // and its neighbours on the same piece (one-sided at the ends of a piece): second order
  // on smooth boundaries, also at the shifted nodes next to a corner.
  std::vector<double> strain(n, 0.0);
  for (const auto& nodes : mesh.piece_nodes) {
    const Index m = static_cast<Index>(nodes.size());
    if (m < 2) continue;
    std::vector<double> arc(m, 0.0);
    for (Index k = 1; k < m; ++k)
      arc[k] = arc[k - 1] + (mesh.nodes[nodes[k]].position - mesh.nodes[nodes[k - 1]].position).norm();
    for (Index k = 0; k < m; ++k) {
      const Index i = nodes[k];
      Vec2 du_ds;
      if (m == 2) {
        du_ds = (solution.displacement[nodes[1]] - solution.displacement[nodes[0]]) / (arc[1] - arc[0]);
      } else {
        const Index first = std::clamp<Index>(k - 1, 0, m - 3);
        // Derivative at arc[k] of the Lagrange quadratic through first, first+1, first+2.
        du_ds = Vec2::Zero();
        for (Index a = first; a < first + 3; ++a) {
          double weight = 0.0;
          for (Index b = first; b < first + 3; ++b) {
            if (b == a) continue;
            double term = 1.0 / (arc[a] - arc[b]);
            for (Index c = first; c < first + 3; ++c)
              if (c != a && c != b) term *= (arc[k] - arc[c]) / (arc[a] - arc[c]);
            weight += term;
          }
          du_ds += weight * solution.displacement[nodes[a]];
        }
      }
      const Vec2& normal = mesh.nodes[i].normal;
      strain[i] = Vec2(-normal.y(), normal.x()).dot(du_ds);
    }
  }
  const double mu = material.shear_modulus();
  const double E = material.young_modulus, nu = material.poisson_ratio;
  const double nu_kernel = kernel_poisson_ratio(type, material);
  std::vector<StressTensor> stresses(n);
  for (Index i = 0; i < n; ++i) {
    const auto& node = mesh.nodes[i];
    const Mat2 q = local_frame(node.normal);
    const Vec2 p_local = q.transpose() * solution.traction[i];
    const double s_nn = p_local[0], s_ns = p_local[1];
    double e_ss = strain[i];
    double s_ss = 0.0, s33 = 0.0;
    if (type == AnalysisType::axisymmetric) {
      const double r = node.position.x();
      const Vec2 s_dir = q.col(1);
      double e_tt;
      if (std::abs(r) > 1e-9 * mesh.scale)
        e_tt = solution.displacement[i].x() / r;
      else  // on the axis u_r / r -> du_r/dr, which is e_ss where the surface is radial
        e_tt = e_ss * (std::abs(s_dir.x()) > 0.5 ? 1.0 : 0.0);
      if (plastic_strain) {  // Hooke's law on eps - eps_p: the tangential and hoop plastic strains taken off
        const auto& ep = (*plastic_strain)[static_cast<std::size_t>(i)];
        e_tt -= ep[2];
        const double ep12 = plasticity::component12(ep);
        e_ss -= s_dir.x() * s_dir.x() * ep[0] + s_dir.y() * s_dir.y() * ep[1] + 2.0 * s_dir.x() * s_dir.y() * ep12;
      }
      const double a = E * e_ss + nu * s_nn, b = E * e_tt + nu * s_nn;
      s_ss = (a + nu * b) / (1.0 - nu * nu);
      s33 = (b + nu * a) / (1.0 - nu * nu);
    } else if (plastic_strain) {
      // Hooke's law on the elastic strain eps - eps_p [SimoHughes1998, ch. 2]: the tangential
      // and out-of-plane plastic strains taken off, sigma_nn given.
      const auto& ep = (*plastic_strain)[static_cast<std::size_t>(i)];
      const Vec2 t = q.col(1);
      const double ep12 = plasticity::component12(ep);
      const double ee_ss = e_ss - (t.x() * t.x() * ep[0] + t.y() * t.y() * ep[1] + 2.0 * t.x() * t.y() * ep12);
      if (type == AnalysisType::plane_stress) {
        s_ss = nu * s_nn + E * ee_ss;
      } else {
        const double lambda = 2.0 * mu * nu / (1.0 - 2.0 * nu), ee_33 = -ep[2];
        const double ee_nn = (s_nn - lambda * (ee_ss + ee_33)) / (lambda + 2.0 * mu);
        const double trace = ee_nn + ee_ss + ee_33;
        s_ss = lambda * trace + 2.0 * mu * ee_ss;
        s33 = lambda * trace + 2.0 * mu * ee_33;
      }
    } else {
      s_ss = (nu_kernel * s_nn + 2.0 * mu * e_ss) / (1.0 - nu_kernel);  // section I.6
    }
    Mat2 local;
    local << s_nn, s_ns, s_ns, s_ss;
    const Mat2 global = q * local * q.transpose();
    StressTensor& s = stresses[i];
    s.s11 = global(0, 0);
    s.s22 = global(1, 1);
    s.s12 = global(0, 1);
    s.s33 = type == AnalysisType::axisymmetric || (plastic_strain && type == AnalysisType::plane_strain)
                ? s33
                : out_of_plane_stress(type, material, s.s11, s.s22);
  }
  for (Index i = 0; i < mesh.node_count(); ++i)
    if (!solution.displacement[i].allFinite() || !solution.traction[i].allFinite() || !stress_is_finite(stresses[i]))
      throw SolverError("the boundary values at node " + std::to_string(i) + " " +
                        point_text(mesh.nodes[i].position) + " are not finite (check the data for extreme values)");
  return stresses;
}

namespace {

// The axis of an axisymmetric body and its symmetry lines carry no elements and lie inside
// the whole body: a point on one is tested a little off it, on the body's side (on the
// closing segment itself the winding number is ambiguous).
Vec2 off_element_free_pieces(const geometry::BoundaryMesh& mesh, const Vec2& query) {
  for (std::size_t p = 0; p < mesh.piece_skipped.size(); ++p) {
    if (!mesh.piece_skipped[p]) continue;
    for (const auto& w : mesh.vertices) {
      if (w.piece_in != static_cast<int>(p)) continue;
      const Vec2 a = mesh.vertices[p].position, along = w.position - a;
      const double f = std::clamp((query - a).dot(along) / along.squaredNorm(), 0.0, 1.0);
      if ((a + f * along - query).norm() <= 1e-9 * mesh.scale)
        return query + 1e-6 * mesh.scale * Vec2(-along.y(), along.x()).normalized();
    }
  }
  return query;
}

}  // namespace

bool point_inside(const geometry::BoundaryMesh& mesh, const Vec2& query, double tolerance) {
  const Vec2 point = off_element_free_pieces(mesh, query);
  // Outside the bounding box (or not a number): outside, before any product can overflow.
  if (!point.allFinite()) return false;
  Vec2 lo = mesh.elements.empty() ? point : mesh.elements.front().start, hi = lo;
  for (const auto& e : mesh.elements) {
    lo = lo.cwiseMin(e.start).cwiseMin(e.end);
    hi = hi.cwiseMax(e.start).cwiseMax(e.end);
  }
  for (const auto& v : mesh.vertices) lo = lo.cwiseMin(v.position), hi = hi.cwiseMax(v.position);
  if ((point.array() < lo.array()).any() || (point.array() > hi.array()).any()) return false;
  double winding = 0.0;
  for (const auto& e : mesh.elements) {
    const Vec2 a = e.start - point, b = e.end - point;
    winding += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  // Axis pieces carry no elements: close the meridian polygon along the axis. Vertex p is
  // the start of piece p; its end is the vertex whose incoming piece is p.
  for (std::size_t p = 0; p < mesh.piece_skipped.size(); ++p) {
    if (!mesh.piece_skipped[p]) continue;
    for (const auto& w : mesh.vertices) {
      if (w.piece_in != static_cast<int>(p)) continue;
      const Vec2 a = mesh.vertices[p].position - point, b = w.position - point;
      winding += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  }
  if (std::abs(winding) < std::numbers::pi) return false;
  return project_on_boundary(mesh, query).distance > tolerance;
}

BoundaryProjection project_on_boundary(const geometry::BoundaryMesh& mesh, const Vec2& point) {
  BoundaryProjection best;
  best.distance = std::numeric_limits<double>::infinity();
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& e = mesh.elements[k];
    const double f = std::clamp((point - e.start).dot(e.tangent) / e.length, 0.0, 1.0);
    const double d = (e.start + f * (e.end - e.start) - point).norm();
    if (d < best.distance) best = {d, k, f};
  }
  return best;
}

Vec2 interpolate_on_element(const geometry::BoundaryElement& element, const std::vector<Vec2>& nodal,
                            double fraction) {
  Vec2 value = Vec2::Zero();
  for (int a = 0; a < element.node_count; ++a)
    value += element.shape(a, fraction) * nodal[element.nodes[a]];
  return value;
}

namespace {

template <class Value, class Accumulate>
void for_vertex_sides(const geometry::BoundaryMesh& mesh, Index vertex, Accumulate&& accumulate) {
  const auto& v = mesh.vertices[vertex];
  for (Index e : {v.element_in, v.element_out}) {
    if (e < 0) continue;
    const auto& element = mesh.elements[e];
    const double f = e == v.element_in ? 1.0 : 0.0;
    for (int a = 0; a < element.node_count; ++a) accumulate(element.nodes[a], element.shape(a, f));
  }
}

int vertex_sides(const geometry::BoundaryMesh& mesh, Index vertex) {
  const auto& v = mesh.vertices[vertex];
  return (v.element_in >= 0) + (v.element_out >= 0);
}

}  // namespace

Vec2 vector_at_vertex(const geometry::BoundaryMesh& mesh, Index vertex, const std::vector<Vec2>& nodal) {
  Vec2 sum = Vec2::Zero();
  for_vertex_sides<Vec2>(mesh, vertex, [&](Index node, double w) { sum += w * nodal[node]; });
  return sum / std::max(1, vertex_sides(mesh, vertex));
}

StressTensor stress_at_vertex(const geometry::BoundaryMesh& mesh, Index vertex,
                              const std::vector<StressTensor>& nodal) {
  StressTensor sum;
  for_vertex_sides<StressTensor>(mesh, vertex, [&](Index node, double w) {
    sum.s11 += w * nodal[node].s11;
    sum.s22 += w * nodal[node].s22;
    sum.s12 += w * nodal[node].s12;
    sum.s33 += w * nodal[node].s33;
  });
  const double k = 1.0 / std::max(1, vertex_sides(mesh, vertex));
  return {sum.s11 * k, sum.s22 * k, sum.s12 * k, sum.s33 * k};
}

StressTensor stress_at_vertex(const geometry::BoundaryMesh& mesh, const BodyDefinition& body, AnalysisType type,
                              Index vertex, const std::vector<StressTensor>& nodal) {
  StressTensor mean = stress_at_vertex(mesh, vertex, nodal);
  const auto& v = mesh.vertices[vertex];
  // Rows on (s11, s22, s12): a . sigma n = prescribed value.
  std::vector<Eigen::RowVector3d> rows;
  std::vector<double> values;
  for (const auto& [piece, normal] : {std::pair{v.piece_in, v.normal_in}, std::pair{v.piece_out, v.normal_out}}) {
    if (piece < 0 || (!mesh.piece_skipped.empty() && mesh.piece_skipped[piece])) continue;
    const auto& bc = body.conditions.at(piece);
    for (int c = 0; c < 2; ++c) {
      if (bc.kind[c] != ConditionKind::traction) continue;
      Vec2 a = Vec2::Unit(c);
      if (bc.frame == ConditionFrame::local) a = c == 0 ? normal : Vec2(-normal.y(), normal.x());
      rows.emplace_back(a.x() * normal.x(), a.y() * normal.y(), a.x() * normal.y() + a.y() * normal.x());
      values.push_back(bc.value_at(c, v.position));
    }
  }
  if (rows.empty()) return mean;
  Eigen::MatrixXd b(static_cast<Index>(rows.size()), 3);
  Eigen::VectorXd d(static_cast<Index>(rows.size()));
  const Eigen::Vector3d sigma_mean(mean.s11, mean.s22, mean.s12);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    b.row(static_cast<Index>(k)) = rows[k];
    d[static_cast<Index>(k)] = values[k] - rows[k].dot(sigma_mean);
  }
  // Smallest correction that meets the data (least squares if they conflict).
  const Eigen::Vector3d correction = b.completeOrthogonalDecomposition().solve(d);
  const Eigen::Vector3d sigma = sigma_mean + correction;
  mean.s11 = sigma[0];
  mean.s22 = sigma[1];
  mean.s12 = sigma[2];
  if (type == AnalysisType::plane_strain) mean.s33 = body.material.poisson_ratio * (sigma[0] + sigma[1]);
  if (type == AnalysisType::plane_stress) mean.s33 = 0.0;
  return mean;
}

namespace {

// Calls add(element, S) for the element and for each of its images across the body's
// symmetry lines (geometry/symmetry.hpp), whose nodal values are S times the element's.
template <class Add>
void for_element_and_images(const geometry::BoundaryMesh& mesh, const geometry::BoundaryElement& element, Add&& add) {
  add(element, Mat2::Identity());
  for (const auto& image : mesh.images) add(geometry::image_element(element, image), image.matrix);
}

}  // namespace

Vec2 somigliana_displacement(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                             const BoundarySolution& solution, const Vec2& point) {
  Vec2 u = Vec2::Zero();
  for (const auto& element : mesh.elements)
    for_element_and_images(mesh, element, [&](const geometry::BoundaryElement& e, const Mat2& S) {
      const auto influence = integrator.influence(point, e, -1);
      for (int a = 0; a < e.node_count; ++a) {
        const Index j = e.nodes[a];
        // u_k(x) = int U_ki p_i - T_ki u_i  (I.11)
        u += influence.G[a] * (S * solution.traction[j]) - influence.H[a] * (S * solution.displacement[j]);
      }
    });
  return u;
}

StressTensor somigliana_stress(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                               const BoundarySolution& solution, const Vec2& point) {
  Mat2 sigma = Mat2::Zero();
  double hoop = 0.0;
  const bool axisymmetric = integrator.type() == AnalysisType::axisymmetric;
  const auto kelvin = kernels::KelvinPlane::from(integrator.type(), integrator.material());
  const auto axi = integration::AxisymmetricKelvin::from(integrator.material());
  for (const auto& element : mesh.elements)
    for_element_and_images(mesh, element, [&](const geometry::BoundaryElement& e, const Mat2& S) {
      if (axisymmetric) {
        const auto s = integration::integrate_axisymmetric_element_stress(axi, point, e);
        for (int a = 0; a < e.node_count; ++a) {
          const Vec2 p = S * solution.traction[e.nodes[a]], u = S * solution.displacement[e.nodes[a]];
          for (int k = 0; k < 2; ++k) {
            sigma += s.in_plane.D[a][k] * p[k] - s.in_plane.S[a][k] * u[k];
            hoop += s.hoop_D[a][k] * p[k] - s.hoop_S[a][k] * u[k];
          }
        }
      } else {
        const auto s = integration::integrate_plane_element_stress(kelvin, point, e);
        for (int a = 0; a < e.node_count; ++a) {
          const Vec2 p = S * solution.traction[e.nodes[a]], u = S * solution.displacement[e.nodes[a]];
          // sigma_ij(x) = int D_kij p_k - S_kij u_k  (I.14)
          for (int k = 0; k < 2; ++k) sigma += s.D[a][k] * p[k] - s.S[a][k] * u[k];
        }
      }
    });
  StressTensor result{sigma(0, 0), sigma(1, 1), 0.5 * (sigma(0, 1) + sigma(1, 0)), 0.0};
  result.s33 = axisymmetric ? hoop
                            : out_of_plane_stress(integrator.type(), integrator.material(), result.s11,
                                                  result.s22);
  return result;
}

InteriorSolution interior_values(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                                 const BoundarySolution& solution, const std::vector<Vec2>& points,
                                 const ProgressCallback& progress, const DomainTerm& domain_term) {
  // Somigliana's displacement and stress at y, with the domain term.
  const auto values_at = [&](const Vec2& y, Vec2* u, StressTensor& s) {
    Vec2 displacement = u ? somigliana_displacement(mesh, integrator, solution, y) : Vec2::Zero();
    s = somigliana_stress(mesh, integrator, solution, y);
    if (domain_term) domain_term(y, displacement, s);
    if (u) *u = displacement;
  };
  InteriorSolution result;
  result.points = points;
  const Index m = static_cast<Index>(points.size());
  result.displacement.resize(m);
  result.stress.resize(m);
  std::atomic<Index> done{0};
  PhaseProgress phase(progress, "interior points");
  phase.start();
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 4)
  for (Index k = 0; k < m; ++k) {
    if (errors.failed()) continue;
    errors.run([&] {
    const Vec2& x = points[k];
    const auto projection = project_on_boundary(mesh, x);
    const auto& element = mesh.elements[projection.element];
    const double safe_distance = 0.5 * element.length;
    if (projection.distance >= safe_distance || solution.stress.empty()) {
      values_at(x, &result.displacement[k], result.stress[k]);
    } else {
      StressTensor ignored;
      values_at(x, &result.displacement[k], ignored);
      // Between the boundary stress at the projection and the Somigliana stress at the
      // safe distance along the inward normal.
      const Vec2 foot = element.start + projection.fraction * (element.end - element.start);
      const Vec2 inside = foot - safe_distance * element.normal;
      StressTensor far;
      values_at(inside, nullptr, far);
      StressTensor near;
      for (int a = 0; a < element.node_count; ++a) {
        const double w = element.shape(a, projection.fraction);
        const StressTensor& s = solution.stress[element.nodes[a]];
        near.s11 += w * s.s11;
        near.s22 += w * s.s22;
        near.s12 += w * s.s12;
        near.s33 += w * s.s33;
      }
      const double t = projection.distance / safe_distance;
      StressTensor& s = result.stress[k];
      s.s11 = (1 - t) * near.s11 + t * far.s11;
      s.s22 = (1 - t) * near.s22 + t * far.s22;
      s.s12 = (1 - t) * near.s12 + t * far.s12;
      s.s33 = (1 - t) * near.s33 + t * far.s33;
    }
    const Index count = ++done;
    if (phase && omp_get_thread_num() == 0)  // the listener hears the calling thread only
      phase.report(static_cast<double>(count) / static_cast<double>(m));
    });
  }
  errors.rethrow();
  phase.finish();
  for (std::size_t i = 0; i < result.points.size(); ++i)
    if (!result.displacement[i].allFinite() || !stress_is_finite(result.stress[i]))
      throw SolverError("the interior values at " + point_text(result.points[i]) +
                        " are not finite: the boundary solution broke down or the point lies on the boundary");
  return result;
}

}  // namespace bemcontact::bem

namespace bemcontact::bem {

InteriorSelection select_interior_points(const geometry::BoundaryMesh& mesh, const std::vector<InteriorPoint>& points) {
  InteriorSelection selection;
  const double tolerance = 1e-9 * mesh.scale;
  for (const auto& p : points) {
    if (point_inside(mesh, p.position, tolerance)) {
      selection.inside.push_back(p.position);
      selection.grid_index.push_back(p.grid_index);
    } else if (p.from_grid) {
      selection.dropped.push_back(p.position);
    } else {
      selection.listed_outside.push_back(&p);
    }
  }
  return selection;
}

InteriorSolution interior_values(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                                 const BoundarySolution& solution, InteriorSelection selection,
                                 const ProgressCallback& progress, const DomainTerm& domain_term) {
  auto result = interior_values(mesh, integrator, solution, selection.inside, progress, domain_term);
  result.grid_index = std::move(selection.grid_index);
  result.dropped_points = std::move(selection.dropped);
  return result;
}

}  // namespace bemcontact::bem
