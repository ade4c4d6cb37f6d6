#include "bemcontact/bem/assembly.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <vector>

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

}  // namespace

std::array<Vec2, geometry::kMaxElementNodes> radial_expansion_traction(const Material& material,
                                                                        const geometry::BoundaryElement& element) {
  const Mat2 sigma = radial_expansion_stress(material);
  std::array<Vec2, geometry::kMaxElementNodes> traction;
  for (int a = 0; a < element.node_count; ++a)
    traction[a] = sigma * (element.arc ? element.normal_at(element.node_fraction[a]) : element.normal);
  return traction;
}

std::vector<Mat2> diagonal_blocks_from_exact_fields(const geometry::BoundaryMesh& mesh, AnalysisType type,
                                                    const Matrix& translation_sums, const Vector& radial_residual) {
  const Index n = mesh.node_count();
  std::vector<Mat2> diagonal(n);
  if (type != AnalysisType::axisymmetric) {
    for (Index i = 0; i < n; ++i) diagonal[i] = -translation_sums.middleRows<2>(2 * i);
    return diagonal;
  }
  // The radial expansion's traction is taken on the elements (sigma n_e, constant on a
  // straight one), not interpolated from the nodes' true normals: on the polygon the field
  // then satisfies every row exactly. Nodal tractions on curved pieces would leave an
  // O(h^2 / R^2) residual everywhere, which the division by r_i blows up near the axis (and
  // which the axis rows, r_i = 0, cannot absorb at all).
  for (Index i = 0; i < n; ++i) {
    diagonal[i].col(1) = -translation_sums.block<2, 1>(2 * i, 1);
    if (node_on_axis(mesh, i))
      diagonal[i].col(0).setZero();  // multiplies u_r = 0
    else
      diagonal[i].col(0) = radial_residual.segment<2>(2 * i) / mesh.nodes[i].position.x();
  }
  return diagonal;
}

namespace {

// Sum over all node columns of each 2-row block, by columns (contiguous in memory); the
// diagonal blocks hold no direct part yet, so this is the sum over j != i (and the images).
Matrix column_sums(const Matrix& h) {
  const Index n = h.cols() / 2;
  Matrix sums = Matrix::Zero(h.rows(), 2);
  constexpr Index chunk = 256;
  const Index chunks = (h.rows() + chunk - 1) / chunk;
#pragma omp parallel for schedule(static)
  for (Index c = 0; c < chunks; ++c) {
    const Index r0 = c * chunk, rows = std::min(chunk, h.rows() - r0);
    for (Index j = 0; j < n; ++j) {
      sums.col(0).segment(r0, rows) += h.col(2 * j).segment(r0, rows);
      sums.col(1).segment(r0, rows) += h.col(2 * j + 1).segment(r0, rows);
    }
  }
  return sums;
}

// Elements in groups that share no node, so that each group can fill its columns of H and
// G in parallel without two threads touching one column (each node has at most two
// elements, so three groups suffice; the order of the sums is fixed).
std::vector<std::vector<Index>> elements_by_colour(const geometry::BoundaryMesh& mesh) {
  std::vector<std::vector<Index>> node_elements(mesh.node_count());
  for (Index e = 0; e < mesh.element_count(); ++e)
    for (int a = 0; a < mesh.elements[e].node_count; ++a) node_elements[mesh.elements[e].nodes[a]].push_back(e);
  std::vector<int> colour(mesh.element_count(), -1);
  std::vector<std::vector<Index>> groups;
  for (Index e = 0; e < mesh.element_count(); ++e) {
    std::vector<bool> taken;
    for (int a = 0; a < mesh.elements[e].node_count; ++a)
      for (Index other : node_elements[mesh.elements[e].nodes[a]])
        if (colour[other] >= 0) {
          if (static_cast<std::size_t>(colour[other]) >= taken.size()) taken.resize(colour[other] + 1, false);
          taken[colour[other]] = true;
        }
    int c = 0;
    while (static_cast<std::size_t>(c) < taken.size() && taken[c]) ++c;
    colour[e] = c;
    if (static_cast<std::size_t>(c) >= groups.size()) groups.resize(c + 1);
    groups[c].push_back(e);
  }
  return groups;
}

}  // namespace

Matrix image_translation_sums(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator) {
  const Index n = mesh.node_count();
  Matrix sums = Matrix::Zero(2 * n, 2);
  std::vector<std::vector<geometry::BoundaryElement>> segments(mesh.images.size());
  for (std::size_t k = 0; k < mesh.images.size(); ++k)
    for (const auto& segment : mesh.symmetry_segments) segments[k].push_back(geometry::image_element(segment, mesh.images[k]));
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    Mat2 sum = Mat2::Zero();
    for (std::size_t k = 0; k < mesh.images.size(); ++k) {
      // B_k = sum_j of image k's H blocks at node i = -int T over its image segments.
      Mat2 b = Mat2::Zero();
      for (const auto& segment : segments[k]) {
        const auto influence = integrator.influence(mesh.nodes[i].position, segment, -1);
        b -= influence.H[0] + influence.H[1];
      }
      sum += b * (Mat2::Identity() - mesh.images[k].matrix);
    }
    sums.middleRows<2>(2 * i) = sum;
  }
  return sums;
}

InfluenceMatrices assemble_influence_matrices(const geometry::BoundaryMesh& mesh,
                                              const ElementIntegrator& integrator,
                                              const ProgressCallback& progress) {
  const Index n = mesh.node_count();
  InfluenceMatrices m{Matrix(2 * n, 2 * n), Matrix(2 * n, 2 * n)};
  // Zero the columns in parallel (first touch spreads the pages over both cores' work).
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < 2 * n; ++j) {
    m.H.col(j).setZero();
    m.G.col(j).setZero();
  }
  std::atomic<Index> elements_done{0};
  PhaseProgress phase(progress, "assembly of H and G");
  phase.start();
  ParallelErrors errors;
  const bool axisymmetric = integrator.type() == AnalysisType::axisymmetric;
  Vector radial_traction_integral = Vector::Zero(axisymmetric ? 2 * n : 0);
  // Element by element, all sources: each element fills the columns of its nodes from top
  // to bottom (contiguous in column-major storage). Elements of one colour share no node,
  // so no column is written by two threads, and every sum runs in a fixed order: the
  // result does not depend on the thread count.
  // In axisymmetry each element also adds int_e U sigma n_e (the radial expansion's traction
  // on it) to every row. Elements go in batches: each keeps its contribution apart, and the
  // batch's contributions are summed in element order afterwards, so that the sum does not
  // depend on the threads either.
  constexpr std::size_t batch = 64;
  Matrix contributions(axisymmetric ? 2 * n : 0, axisymmetric ? static_cast<Index>(batch) : 0);
  // With symmetry lines each element also acts through its images (geometry/symmetry.hpp):
  // H_ij += H'_k S_k, G_ij += G'_k S_k, in every block (the diagonal ones too: an image is
  // never singular). The diagonal blocks then follow as below with image_translation_sums.
  const bool images = !mesh.images.empty();
  for (const auto& group : elements_by_colour(mesh)) {
    for (std::size_t first = 0; first < group.size(); first += batch) {
      const std::size_t count = std::min(batch, group.size() - first);
#pragma omp parallel for schedule(dynamic, 2)
      for (std::size_t k = 0; k < count; ++k) {
        if (errors.failed()) continue;
        errors.run([&] {
          const auto& element = mesh.elements[group[first + k]];
          const auto nodal_traction = radial_expansion_traction(integrator.material(), element);
          std::vector<geometry::BoundaryElement> image_elements;
          for (const auto& image : mesh.images) image_elements.push_back(geometry::image_element(element, image));
          for (Index i = 0; i < n; ++i) {
            int source_node = -1;
            for (int a = 0; a < element.node_count; ++a)
              if (element.nodes[a] == i) source_node = a;
            const auto influence = integrator.influence(mesh.nodes[i].position, element, source_node);
            Vec2 traction_term = Vec2::Zero();
            for (int a = 0; a < element.node_count; ++a) {
              const Index j = element.nodes[a];
              m.G.block<2, 2>(2 * i, 2 * j) += influence.G[a];
              if (a != source_node) m.H.block<2, 2>(2 * i, 2 * j) += influence.H[a];
              traction_term += influence.G[a] * nodal_traction[a];
            }
            if (images)
              for (std::size_t q = 0; q < mesh.images.size(); ++q) {
                const Mat2& S = mesh.images[q].matrix;
                const auto image = integrator.influence(mesh.nodes[i].position, image_elements[q], -1);
                for (int a = 0; a < element.node_count; ++a) {
                  const Index j = element.nodes[a];
                  m.G.block<2, 2>(2 * i, 2 * j) += image.G[a] * S;
                  m.H.block<2, 2>(2 * i, 2 * j) += image.H[a] * S;
                  traction_term += image.G[a] * S * nodal_traction[a];
                }
              }
            if (axisymmetric) contributions.block<2, 1>(2 * i, static_cast<Index>(k)) = traction_term;
          }
          const Index done = ++elements_done;
          if (phase && omp_get_thread_num() == 0)  // the listener hears the calling thread only
            phase.report(static_cast<double>(done) / static_cast<double>(mesh.element_count()));
        });
      }
      errors.rethrow();
      if (axisymmetric)
        for (std::size_t k = 0; k < count; ++k) radial_traction_integral += contributions.col(static_cast<Index>(k));

    }
  }
  // sum over j != i of H_ij times the translations: the diagonal blocks hold only the images'
  // part here, which the sum takes in, and the images' antisymmetric part is added back.
  Matrix translation_sums = column_sums(m.H);
  if (images) translation_sums += image_translation_sums(mesh, integrator);
  Vector radial_residual;
  if (axisymmetric) {
    Vector radial_u = Vector::Zero(2 * n);
    for (Index j = 0; j < n; ++j) radial_u[2 * j] = mesh.nodes[j].position.x();
    radial_residual = radial_traction_integral - m.H * radial_u;
  }
  const auto diagonal = diagonal_blocks_from_exact_fields(mesh, integrator.type(), translation_sums, radial_residual);
  for (Index i = 0; i < n; ++i) m.H.block<2, 2>(2 * i, 2 * i) += diagonal[i];
  phase.finish();
  return m;
}

}  // namespace bemcontact::bem
