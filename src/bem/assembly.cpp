#include "bemcontact/bem/assembly.hpp"

#include <omp.h>

#include <atomic>
#include <cmath>

#include "bemcontact/core/error.hpp"
#include "bemcontact/core/parallel.hpp"
#include "bemcontact/integration/plane_element.hpp"

namespace bemcontact::bem {

ElementIntegrator::ElementIntegrator(AnalysisType type, const Material& material)
    : type_(type),
      material_(material),
      plane_(kernels::KelvinPlane::from(type, material)),
      axisymmetric_(integration::AxisymmetricKelvin::from(material)) {}

integration::ElementInfluence ElementIntegrator::influence(const Vec2& source,
                                                           const geometry::BoundaryElement& element,
                                                           int source_node) const {
  if (type_ == AnalysisType::axisymmetric)
    return integration::integrate_axisymmetric_element(axisymmetric_, source, element, source_node);
  return integration::integrate_plane_element(plane_, source, element, source_node);
}

bool node_on_axis(const geometry::BoundaryMesh& mesh, Index node) {
  return std::abs(mesh.nodes[node].position.x()) <= 1e-9 * mesh.scale;
}

namespace {

// Stress of the uniform radial expansion u_r = r, u_z = 0: e_rr = e_tt = 1, e_zz = 0.
Mat2 radial_expansion_stress(const Material& material) {
  const double mu = material.shear_modulus();
  const double nu = material.poisson_ratio;
  const double lambda = 2.0 * mu * nu / (1.0 - 2.0 * nu);
  Mat2 sigma;
  sigma << 2.0 * (lambda + mu), 0.0, 0.0, 2.0 * lambda;
  return sigma;
}

void set_diagonal_blocks(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                         InfluenceMatrices& m) {
  const Index n = mesh.node_count();
  const bool axisymmetric = integrator.type() == AnalysisType::axisymmetric;
  Vector radial_u, radial_p;
  if (axisymmetric) {
    radial_u = Vector::Zero(2 * n);
    radial_p = Vector::Zero(2 * n);
    const Mat2 sigma = radial_expansion_stress(integrator.material());
    for (Index j = 0; j < n; ++j) {
      radial_u[2 * j] = mesh.nodes[j].position.x();
      radial_p.segment<2>(2 * j) = sigma * mesh.nodes[j].normal;
    }
  }
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Mat2 off_diagonal_sum = Mat2::Zero();
    for (Index j = 0; j < n; ++j)
      if (j != i) off_diagonal_sum += m.H.block<2, 2>(2 * i, 2 * j);
    if (!axisymmetric) {
      // Rigid translations give zero traction: sum_j H_ij = 0 (section I.4.2, remark).
      m.H.block<2, 2>(2 * i, 2 * i) = -off_diagonal_sum;
      continue;
    }
    // Axial translation (only rigid mode of axisymmetry, section II.3.3) gives the z column.
    m.H.block<2, 1>(2 * i, 2 * i + 1) = -off_diagonal_sum.col(1);
    // The radial expansion gives the r column: H_ii[:, r] r_i = (G p - H' u)_i.
    const double r_i = mesh.nodes[i].position.x();
    if (node_on_axis(mesh, i)) {
      m.H.block<2, 1>(2 * i, 2 * i).setZero();  // multiplies u_r = 0
      continue;
    }
    Eigen::Vector2d residual = m.G.middleRows<2>(2 * i) * radial_p;
    for (Index j = 0; j < n; ++j)
      if (j != i) residual -= m.H.block<2, 1>(2 * i, 2 * j) * radial_u[2 * j];
    m.H.block<2, 1>(2 * i, 2 * i) = residual / r_i;
  }
}

}  // namespace

InfluenceMatrices assemble_influence_matrices(const geometry::BoundaryMesh& mesh,
                                              const ElementIntegrator& integrator,
                                              const ProgressCallback& progress) {
  const Index n = mesh.node_count();
  InfluenceMatrices m{Matrix::Zero(2 * n, 2 * n), Matrix::Zero(2 * n, 2 * n)};
  std::atomic<Index> rows_done{0};
  ParallelErrors errors;
  // One source node per iteration: every entry is written by one thread, so the result
  // does not depend on the thread count.
#pragma omp parallel for schedule(dynamic, 8)
  for (Index i = 0; i < n; ++i) {
    if (errors.failed()) continue;
    errors.run([&] {
    const Vec2& source = mesh.nodes[i].position;
    for (const auto& element : mesh.elements) {
      int source_node = -1;
      for (int a = 0; a < element.node_count; ++a)
        if (element.nodes[a] == i) source_node = a;
      const auto influence = integrator.influence(source, element, source_node);
      for (int a = 0; a < element.node_count; ++a) {
        const Index j = element.nodes[a];
        m.G.block<2, 2>(2 * i, 2 * j) += influence.G[a];
        if (a != source_node) m.H.block<2, 2>(2 * i, 2 * j) += influence.H[a];
      }
    }
    const Index done = ++rows_done;
    if (progress && omp_get_thread_num() == 0) progress("assembly", static_cast<double>(done) / n);
    });
  }
  errors.rethrow();
  set_diagonal_blocks(mesh, integrator, m);
  if (progress) progress("assembly", 1.0);
  return m;
}

}  // namespace bemcontact::bem
