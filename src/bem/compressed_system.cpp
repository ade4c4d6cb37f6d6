#include "bemcontact/bem/compressed_system.hpp"

#include <algorithm>
#include <array>

#include "bemcontact/core/error.hpp"

namespace bemcontact::bem {
namespace {

// Sorted (node, local index) pairs: lookups in a block's node list without O(N) tables.
class NodeIndex {
 public:
  explicit NodeIndex(const std::vector<Index>& nodes) {
    entries_.reserve(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) entries_.emplace_back(nodes[k], static_cast<Index>(k));
    std::sort(entries_.begin(), entries_.end());
  }
  Index find(Index node) const {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair<Index, Index>{node, -1});
    return it != entries_.end() && it->first == node ? it->second : -1;
  }

 private:
  std::vector<std::pair<Index, Index>> entries_;
};

std::vector<Index> unique_nodes(std::vector<Index> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// `options` with the rows by component (HMatrixOptions::row_component): a node's rows x, y,
// x, y, ..., then `extra` rows (the constraints') with the first.
operators::HMatrixOptions rows_by_component(operators::HMatrixOptions options, Index node_rows, Index extra = 0) {
  options.row_component.assign(static_cast<std::size_t>(node_rows + extra), 0);
  for (Index i = 0; i < node_rows; ++i) options.row_component[static_cast<std::size_t>(i)] = static_cast<int>(i % 2);
  return options;
}

// The straight line parallel to an axis (an id >= 0) that all of each node's elements lie on,
// -1 for none: a node where two lines meet, on an arc or an oblique element. On such a line,
// between a point of it and elements of it, s is along the line and n across: ds/dn = 0 and
// s_x s_y = 0, so the plane kernels (Annex A, dimension 2; kernels/kelvin2d.cpp) have
// T_xx = T_yy = 0 (what is left, s_i n_j - s_j n_i, vanishes for i = j) and U_xy = U_yx = 0:
// the zeros of HMatrixOptions::col_null_components. In axisymmetry on the lines z = const
// only (the plane of the ring loads, Annex B: Kelvin's tractions on a plane through the point
// force and its displacements across it vanish the same way; a line r = const is a
// cylinder). Checked on the integrated H and G (CompressedSystem.KernelsVanishWhereTheLinesSayTheyDo).
// None on a body with symmetry images (an element's image leaves its line).
std::vector<int> node_lines(const geometry::BoundaryMesh& mesh, AnalysisType type) {
  std::vector<int> line(static_cast<std::size_t>(mesh.node_count()), -1);
  if (!mesh.images.empty()) return line;
  const bool axisymmetric = type == AnalysisType::axisymmetric;
  std::vector<std::pair<int, double>> keys;  // (0: y = c, 1: x = c; c) of each id
  const auto id_of = [&keys](int axis, double level) {
    for (std::size_t k = 0; k < keys.size(); ++k)
      if (keys[k].first == axis && keys[k].second == level) return static_cast<int>(k);
    keys.emplace_back(axis, level);
    return static_cast<int>(keys.size()) - 1;
  };
  std::vector<char> seen(static_cast<std::size_t>(mesh.node_count()), 0);
  for (const auto& element : mesh.elements) {
    int id = -1;
    if (!element.arc && element.start.y() == element.end.y()) id = id_of(0, element.start.y());
    else if (!element.arc && !axisymmetric && element.start.x() == element.end.x()) id = id_of(1, element.start.x());
    for (int a = 0; a < element.node_count; ++a) {
      const auto node = static_cast<std::size_t>(element.nodes[static_cast<std::size_t>(a)]);
      line[node] = seen[node] && line[node] != id ? -1 : id;
      seen[node] = 1;
    }
  }
  for (std::size_t i = 0; i < line.size(); ++i) {  // the node's own point on the line too
    if (line[i] < 0) continue;
    const auto& [axis, level] = keys[static_cast<std::size_t>(line[i])];
    const Vec2& p = mesh.nodes[i].position;
    if ((axis == 0 ? p.y() : p.x()) != level) line[i] = -1;
  }
  return line;
}

// The place of each node row (2 node + component, below `node_rows`) in a matrix of the
// nodes `index` holds, found once per request rather than once per entry; -1 elsewhere.
std::vector<Index> node_row_places(const std::vector<Index>& rows, const NodeIndex& index, Index node_rows) {
  std::vector<Index> out(rows.size(), -1);
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r] < node_rows) out[r] = 2 * index.find(rows[r] / 2) + rows[r] % 2;
  return out;
}

}  // namespace

InfluenceBlocks::InfluenceBlocks(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator)
    : mesh_(mesh), integrator_(integrator), node_elements_(mesh.node_count()) {
  for (Index e = 0; e < mesh.element_count(); ++e)
    for (int a = 0; a < mesh.elements[e].node_count; ++a) node_elements_[mesh.elements[e].nodes[a]].push_back(e);
}

void InfluenceBlocks::evaluate(const std::vector<Index>& row_nodes, const std::vector<Index>& col_nodes, Matrix& H,
                               Matrix& G) const {
  const Index rows = static_cast<Index>(row_nodes.size()), cols = static_cast<Index>(col_nodes.size());
  H.setZero(2 * rows, 2 * cols);
  G.setZero(2 * rows, 2 * cols);
  const NodeIndex col_index(col_nodes);
  std::vector<Index> elements;
  for (Index j : col_nodes) elements.insert(elements.end(), node_elements_[j].begin(), node_elements_[j].end());
  elements = unique_nodes(std::move(elements));
  // Each row is independent (and summed in element order): the same for any thread count.
#pragma omp parallel for schedule(dynamic, 4) if (rows * static_cast<Index>(elements.size()) > 4096)
  for (Index r = 0; r < rows; ++r) {
    const Index i = row_nodes[r];
    for (Index e : elements) {
      const auto& element = mesh_.elements[e];
      int source_node = -1;
      for (int a = 0; a < element.node_count; ++a)
        if (element.nodes[a] == i) source_node = a;
      const auto influence = integrator_.influence(mesh_.nodes[i].position, element, source_node);
      for (int a = 0; a < element.node_count; ++a) {
        const Index c = col_index.find(element.nodes[a]);
        if (c < 0) continue;
        G.block<2, 2>(2 * r, 2 * c) += influence.G[a];
        if (a != source_node) H.block<2, 2>(2 * r, 2 * c) += influence.H[a];
      }
      for (const auto& map : mesh_.images) {
        const auto image = integrator_.influence(mesh_.nodes[i].position, geometry::image_element(element, map), -1);
        for (int a = 0; a < element.node_count; ++a) {
          const Index c = col_index.find(element.nodes[a]);
          if (c < 0) continue;
          G.block<2, 2>(2 * r, 2 * c) += image.G[a] * map.matrix;
          H.block<2, 2>(2 * r, 2 * c) += image.H[a] * map.matrix;
        }
      }
    }
  }
}

Matrix InfluenceBlocks::image_translation_sums() const { return bem::image_translation_sums(mesh_, integrator_); }

Matrix InfluenceBlocks::radial_traction(const std::vector<Index>& row_nodes, const std::vector<Index>& elements) const {
  const Index rows = static_cast<Index>(row_nodes.size()), cols = static_cast<Index>(elements.size());
  Matrix out = Matrix::Zero(2 * rows, cols);
  std::vector<std::array<Vec2, geometry::kMaxElementNodes>> tractions(elements.size());
  for (Index c = 0; c < cols; ++c) tractions[c] = radial_expansion_traction(integrator_.material(), mesh_.elements[elements[c]]);
#pragma omp parallel for schedule(dynamic, 4) if (rows * cols > 4096)
  for (Index r = 0; r < rows; ++r) {
    const Index i = row_nodes[r];
    for (Index c = 0; c < cols; ++c) {
      const auto& element = mesh_.elements[elements[c]];
      int source_node = -1;
      for (int a = 0; a < element.node_count; ++a)
        if (element.nodes[a] == i) source_node = a;
      const auto influence = integrator_.influence(mesh_.nodes[i].position, element, source_node);
      for (int a = 0; a < element.node_count; ++a) out.block<2, 1>(2 * r, c) += influence.G[a] * tractions[c][a];
      for (const auto& map : mesh_.images) {  // the image's traction is S times the element's
        const auto image = integrator_.influence(mesh_.nodes[i].position, geometry::image_element(element, map), -1);
        for (int a = 0; a < element.node_count; ++a)
          out.block<2, 1>(2 * r, c) += image.G[a] * map.matrix * tractions[c][a];
      }
    }
  }
  return out;
}

CompressedBoundarySystem::CompressedBoundarySystem(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                                                   std::vector<NodeCondition> conditions,
                                                   std::vector<ConstraintEquation> constraints,
                                                   const operators::HMatrixOptions& options, const std::string& what,
                                                   const ProgressCallback& progress)
    : mesh_(mesh),
      traction_scale_(integrator.material().shear_modulus()),
      node_scale_(Vector::Zero(mesh.node_count())),
      conditions_(std::move(conditions)),
      constraints_(std::move(constraints)),
      type_(integrator.type()),
      blocks_(mesh, integrator),
      node_line_(node_lines(mesh, integrator.type())),
      influence_(assemble_influence(options, "the influence matrices of " + what, progress)),
      diagonal_(diagonal_blocks(options, what, progress)),
      system_(assemble_system(options, what, progress)),
      rhs_(prescribed_rhs()) {}

void CompressedBoundarySystem::factorize(bool keep_transposed, const ProgressCallback& progress) {
  PhaseProgress phase(progress, "H-LU factorisation");
  system_.factorize(keep_transposed, phase.fractions());
  phase.finish();
}

operators::RowPartitionedHMatrix CompressedBoundarySystem::assemble_influence(const operators::HMatrixOptions& options,
                                                                              const std::string& what,
                                                                              const ProgressCallback& progress) {
  const Index n = mesh_.node_count();
  for (const auto& element : mesh_.elements)
    for (int a = 0; a < element.node_count; ++a) node_scale_[element.nodes[a]] += element.length;
  node_scale_ = node_scale_.cwiseInverse();
  std::vector<Vec2> row_points(2 * n), col_points(4 * n);
  for (Index i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c) {
      row_points[2 * i + c] = mesh_.nodes[i].position;
      col_points[2 * i + c] = col_points[2 * n + 2 * i + c] = mesh_.nodes[i].position;
    }
  // Columns 0 .. 2N-1: H' (u), 2N .. 4N-1: G (p).
  const auto entries = [this, n](const std::vector<Index>& rows, const std::vector<Index>& cols, double* out) {
    std::vector<Index> row_nodes(rows.size()), col_nodes(cols.size());
    for (std::size_t r = 0; r < rows.size(); ++r) row_nodes[r] = rows[r] / 2;
    for (std::size_t c = 0; c < cols.size(); ++c) col_nodes[c] = (cols[c] % (2 * n)) / 2;
    row_nodes = unique_nodes(std::move(row_nodes));
    col_nodes = unique_nodes(std::move(col_nodes));
    Matrix H, G;
    blocks_.evaluate(row_nodes, col_nodes, H, G);
    const NodeIndex row_index(row_nodes), col_index(col_nodes);
    const Index m = static_cast<Index>(rows.size());
    const std::vector<Index> local_row = node_row_places(rows, row_index, 2 * n);
    for (std::size_t c = 0; c < cols.size(); ++c) {
      const Index dof = cols[c] % (2 * n);
      const bool g_column = cols[c] >= 2 * n;
      const Matrix& source = g_column ? G : H;
      const double scale = (g_column ? traction_scale_ : 1.0) * node_scale_[dof / 2];
      const Index lc = 2 * col_index.find(dof / 2) + dof % 2;
      const double* column = source.col(lc).data();
      for (Index r = 0; r < m; ++r) out[r + static_cast<Index>(c) * m] = scale * column[local_row[static_cast<std::size_t>(r)]];
    }
  };
  // On a line, a u column is zero in its own component's rows (T_xx = T_yy = 0), a p column
  // in the other's (U_xy = 0).
  operators::HMatrixOptions by_component = rows_by_component(options, 2 * n);
  const std::vector<int>& line = node_line_;
  by_component.row_line.resize(static_cast<std::size_t>(2 * n));
  by_component.col_line.resize(static_cast<std::size_t>(4 * n));
  by_component.col_null_components.resize(static_cast<std::size_t>(4 * n));
  for (Index d = 0; d < 2 * n; ++d) {
    const auto at = static_cast<std::size_t>(d);
    by_component.row_line[at] = by_component.col_line[at] = by_component.col_line[at + 2 * n] = line[at / 2];
    by_component.col_null_components[at] = static_cast<unsigned char>(1 << (d % 2));
    by_component.col_null_components[at + 2 * n] = static_cast<unsigned char>(1 << (1 - d % 2));
  }
  PhaseProgress phase(progress, "assembly of H and G");
  operators::RowPartitionedHMatrix influence(row_points, col_points, entries, by_component, what, phase.fractions());
  phase.finish();
  return influence;
}

std::vector<Mat2> CompressedBoundarySystem::diagonal_blocks(const operators::HMatrixOptions& options,
                                                             const std::string& what,
                                                             const ProgressCallback& progress) const {
  // H' times the rigid translations (columns 0, 1) and, in axisymmetry, the radial
  // expansion u_r = r (column 2), in one product.
  const Index n = mesh_.node_count();
  const bool axisymmetric = type_ == AnalysisType::axisymmetric;
  Matrix fields = Matrix::Zero(4 * n, axisymmetric ? 3 : 2);
  for (Index j = 0; j < n; ++j) {
    fields(2 * j, 0) = fields(2 * j + 1, 1) = 1.0 / node_scale_[j];
    if (axisymmetric) fields(2 * j, 2) = mesh_.nodes[j].position.x() / node_scale_[j];
  }
  const Matrix products = influence_.apply(fields);
  Vector radial_residual;
  if (axisymmetric) radial_residual = radial_traction_integral(options, what, progress) - products.col(2);
  Matrix translation_sums = products.leftCols(2);
  if (!mesh_.images.empty()) translation_sums += blocks_.image_translation_sums();
  return diagonal_blocks_from_exact_fields(mesh_, type_, translation_sums, radial_residual);
}

Vector CompressedBoundarySystem::radial_traction_integral(const operators::HMatrixOptions& options,
                                                          const std::string& what,
                                                          const ProgressCallback& progress) const {
  // sum_e int_e U p_e as the product of a compressed (2N x elements) matrix with the
  // elements' lengths; its columns are stored divided by the length, like those of H and G.
  const Index n = mesh_.node_count(), elements = mesh_.element_count();
  std::vector<Vec2> row_points(2 * n), col_points(elements);
  for (Index i = 0; i < n; ++i) row_points[2 * i] = row_points[2 * i + 1] = mesh_.nodes[i].position;
  Matrix lengths(elements, 1);
  for (Index e = 0; e < elements; ++e) {
    const auto& element = mesh_.elements[e];
    Vec2 centre = Vec2::Zero();
    for (int a = 0; a < element.node_count; ++a) centre += mesh_.nodes[element.nodes[a]].position;
    col_points[e] = centre / element.node_count;
    lengths(e, 0) = element.length;
  }
  const auto entries = [this, n, &lengths](const std::vector<Index>& rows, const std::vector<Index>& cols, double* out) {
    std::vector<Index> row_nodes(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) row_nodes[r] = rows[r] / 2;
    row_nodes = unique_nodes(std::move(row_nodes));
    const Matrix values = blocks_.radial_traction(row_nodes, cols);
    const std::vector<Index> local_row = node_row_places(rows, NodeIndex(row_nodes), 2 * n);
    const Index m = static_cast<Index>(rows.size());
    for (std::size_t c = 0; c < cols.size(); ++c)
      for (Index r = 0; r < m; ++r)
        out[r + static_cast<Index>(c) * m] =
            values(local_row[static_cast<std::size_t>(r)], static_cast<Index>(c)) / lengths(cols[c], 0);
  };
  PhaseProgress phase(progress, "diagonal blocks");
  const operators::HMatrix integrals(row_points, col_points, entries, rows_by_component(options, 2 * n),
                                     "the radial expansion's traction integrals of " + what, phase.fractions());
  Vector integral = integrals.apply(lengths).col(0);
  phase.finish();
  return integral;
}

// H and G of these nodes (rows) against those (columns), as InfluenceBlocks::evaluate gives
// them, read from the compressed [H' | G] (its columns' scales taken out): the system's
// assembly then costs no kernel integral, where it took half of the model's.
void CompressedBoundarySystem::influence_blocks(const std::vector<Index>& row_nodes, const std::vector<Index>& col_nodes,
                                                Matrix& H, Matrix& G) const {
  const Index n = mesh_.node_count(), r = static_cast<Index>(row_nodes.size()), c = static_cast<Index>(col_nodes.size());
  std::vector<Index> rows(static_cast<std::size_t>(2 * r)), cols(static_cast<std::size_t>(4 * c));
  for (Index i = 0; i < r; ++i)
    for (int k = 0; k < 2; ++k) rows[static_cast<std::size_t>(2 * i + k)] = 2 * row_nodes[static_cast<std::size_t>(i)] + k;
  for (Index j = 0; j < c; ++j)
    for (int k = 0; k < 2; ++k) {
      const Index dof = 2 * col_nodes[static_cast<std::size_t>(j)] + k;
      cols[static_cast<std::size_t>(2 * j + k)] = dof;
      cols[static_cast<std::size_t>(2 * c + 2 * j + k)] = 2 * n + dof;
    }
  const Matrix values = influence_.entries(rows, cols);
  H.resize(2 * r, 2 * c);
  G.resize(2 * r, 2 * c);
  for (Index j = 0; j < c; ++j) {
    const double scale = node_scale_[col_nodes[static_cast<std::size_t>(j)]];
    H.middleCols(2 * j, 2) = values.middleCols(2 * j, 2) / scale;
    G.middleCols(2 * j, 2) = values.middleCols(2 * c + 2 * j, 2) / (traction_scale_ * scale);
  }
}

operators::HMatrix CompressedBoundarySystem::assemble_system(const operators::HMatrixOptions& options,
                                                             const std::string& what,
                                                             const ProgressCallback& progress) const {
  const Index n = mesh_.node_count(), dofs = 2 * n, extra = static_cast<Index>(constraints_.size());
  std::vector<Vec2> points(dofs + extra);
  for (Index d = 0; d < dofs; ++d) points[d] = mesh_.nodes[d / 2].position;
  for (Index q = 0; q < extra; ++q) points[dofs + q] = mesh_.nodes[constraints_[q].reaction_node].position;
  // Node of each row or column unknown (-1: a constraint row).
  const auto column_node = [this, dofs](Index col) {
    return col < dofs ? col / 2 : constraints_[col - dofs].reaction_node;
  };
  // Unknown tractions (prescribed displacement) and reactions: columns of -G.
  const auto traction_column_of = [this, dofs](Index col) {
    return col >= dofs || conditions_[col / 2].kind[col % 2] == ConditionKind::displacement;
  };
  const auto entries = [this, n, dofs, column_node, traction_column_of](const std::vector<Index>& rows, const std::vector<Index>& cols,
                                                      double* out) {
    const Index m = static_cast<Index>(rows.size());
    std::vector<Index> row_nodes, col_nodes;
    for (Index r : rows)
      if (r < dofs) row_nodes.push_back(r / 2);
    for (Index c : cols) col_nodes.push_back(column_node(c));
    row_nodes = unique_nodes(std::move(row_nodes));
    col_nodes = unique_nodes(std::move(col_nodes));
    Matrix H, G;
    if (!row_nodes.empty()) influence_blocks(row_nodes, col_nodes, H, G);
    const NodeIndex row_index(row_nodes), col_index(col_nodes);
    const std::vector<Index> local_row = node_row_places(rows, row_index, dofs);
    for (std::size_t cc = 0; cc < cols.size(); ++cc) {
      const Index col = cols[cc];
      double* column = out + static_cast<Index>(cc) * m;
      const Index j = column_node(col);
      const Index lc = 2 * col_index.find(j);
      // The column's 2 global components (rows of the node block) to combine.
      const bool traction_column = traction_column_of(col);  // -G, or H (unknown displacement)
      // The column's scale (unknown_scale): A_s = A S.
      const double scale = node_scale_[j] * (traction_column ? traction_scale_ : 1.0);
      const Vec2 weights = col < dofs ? Vec2(conditions_[j].frame.col(col % 2))  // the frame's axis
                                      : constraints_[col - dofs].reaction_component == 0 ? Vec2(1.0, 0.0)
                                                                                         : Vec2(0.0, 1.0);
      for (Index rr = 0; rr < m; ++rr) {
        const Index row = rows[rr];
        if (row >= dofs) {  // a constraint row: its displacement terms
          double value = 0.0;
          if (col < dofs)
            for (const auto& [d, coefficient] : constraints_[row - dofs].displacement_terms)
              if (d == col) value += coefficient;
          column[rr] = scale * value;
          continue;
        }
        const Index i = row / 2;
        if (row % 2 == 0 && conditions_[i].on_axis) {  // p_r = 0 (u_r = 0) on the axis, as build_boundary_system
          column[rr] = col == row ? scale : 0.0;
          continue;
        }
        const Index lr = local_row[static_cast<std::size_t>(rr)];
        if (traction_column) {
          column[rr] = -scale * (G(lr, lc) * weights[0] + G(lr, lc + 1) * weights[1]);
        } else {
          // The diagonal block: its direct part from exact fields, and its images' part.
          const Vec2 h_row = i == j ? Vec2(diagonal_[i].row(row % 2).transpose() + Vec2(H(lr, lc), H(lr, lc + 1)))
                                    : Vec2(H(lr, lc), H(lr, lc + 1));
          column[rr] = scale * h_row.dot(weights);
        }
      }
    }
  };
  // On a line (as [H' | G]'s): a displacement column (H times its frame axis w) is zero in
  // the rows of component k when w's other component is 0, a traction column (-G w) when w's
  // own is; constraint rows lie on no line.
  operators::HMatrixOptions by_component = rows_by_component(options, dofs, extra);
  const std::vector<int>& line = node_line_;
  by_component.row_line.assign(static_cast<std::size_t>(dofs + extra), -1);
  by_component.col_line.resize(static_cast<std::size_t>(dofs + extra));
  by_component.col_null_components.assign(static_cast<std::size_t>(dofs + extra), 0);
  for (Index col = 0; col < dofs + extra; ++col) {
    const auto at = static_cast<std::size_t>(col);
    if (col < dofs) by_component.row_line[at] = line[at / 2];
    by_component.col_line[at] = line[static_cast<std::size_t>(column_node(col))];
    const Vec2 w = col < dofs ? Vec2(conditions_[col / 2].frame.col(col % 2))
                              : constraints_[col - dofs].reaction_component == 0 ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
    const bool traction = traction_column_of(col);
    for (int k = 0; k < 2; ++k)
      if ((traction ? w[k] : w[1 - k]) == 0.0) by_component.col_null_components[at] |= static_cast<unsigned char>(1 << k);
  }
  PhaseProgress phase(progress, "system assembly");
  operators::HMatrix system(points, points, entries, by_component, what, phase.fractions());
  phase.finish();
  return system;
}

Matrix CompressedBoundarySystem::apply_h_minus_g(const Matrix& U, const Matrix& P) const {
  const Index n = mesh_.node_count();
  Matrix x(4 * n, U.cols());
  for (Index j = 0; j < U.cols(); ++j) x.col(j) = influence_input(U.col(j), -P.col(j));
  Matrix y = influence_.apply(x);
  for (Index i = 0; i < n; ++i) y.middleRows<2>(2 * i) += diagonal_[i] * U.middleRows<2>(2 * i);
  return y;
}

Matrix CompressedBoundarySystem::boundary_rhs(const Matrix& U, const Matrix& P) const {
  if (U.rows() != 2 * mesh_.node_count() || P.rows() != U.rows() || P.cols() != U.cols())
    throw Error("CompressedBoundarySystem: boundary values of the wrong size");
  Matrix rhs = -apply_h_minus_g(U, P);
  for (Index i = 0; i < mesh_.node_count(); ++i)
    if (conditions_[i].on_axis) rhs.row(2 * i).setZero();  // the axis rows' equation p_r = 0
  return rhs;
}

Vector CompressedBoundarySystem::prescribed_rhs() const {
  const Index n = mesh_.node_count(), dofs = 2 * n;
  Vector u = Vector::Zero(dofs), p = Vector::Zero(dofs);
  for (Index i = 0; i < n; ++i) {
    Vec2 u_frame = Vec2::Zero(), p_frame = Vec2::Zero();
    for (int c = 0; c < 2; ++c)
      (conditions_[i].kind[c] == ConditionKind::displacement ? u_frame : p_frame)[c] = conditions_[i].value[c];
    u.segment<2>(2 * i) = conditions_[i].frame * u_frame;
    p.segment<2>(2 * i) = conditions_[i].frame * p_frame;
  }
  Vector b(dofs + static_cast<Index>(constraints_.size()));
  b.head(dofs) = boundary_rhs(u, p);  // G p - H u
  for (std::size_t k = 0; k < constraints_.size(); ++k) b[dofs + static_cast<Index>(k)] = constraints_[k].value;
  return b;
}

Matrix CompressedBoundarySystem::reaction_columns() const {
  const Index n = mesh_.node_count(), k = static_cast<Index>(constraints_.size());
  Matrix x = Matrix::Zero(4 * n, k);
  for (Index q = 0; q < k; ++q) {
    const Index node = constraints_[q].reaction_node;
    x(2 * n + 2 * node + constraints_[q].reaction_component, q) = 1.0 / (traction_scale_ * node_scale_[node]);
  }
  return -influence_.apply(x);
}

Vector CompressedBoundarySystem::unknown_scale() const {
  const Index n = mesh_.node_count();
  Vector scale(2 * n + static_cast<Index>(constraints_.size()));
  for (Index i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c)  // a displacement unknown where the traction is prescribed (H column)
      scale[2 * i + c] = node_scale_[i] * (conditions_[i].kind[c] == ConditionKind::traction ? 1.0 : traction_scale_);
  for (std::size_t q = 0; q < constraints_.size(); ++q)
    scale[2 * n + static_cast<Index>(q)] = node_scale_[constraints_[q].reaction_node] * traction_scale_;
  return scale;
}

Vector CompressedBoundarySystem::influence_input(const Vector& u, const Vector& p) const {
  const Index n = mesh_.node_count();
  Vector x(4 * n);
  for (Index i = 0; i < n; ++i) {
    x.segment<2>(2 * i) = u.segment<2>(2 * i) / node_scale_[i];
    x.segment<2>(2 * n + 2 * i) = p.segment<2>(2 * i) / (traction_scale_ * node_scale_[i]);
  }
  return x;
}

Vector CompressedBoundarySystem::apply(const Vector& y) const {
  return system_.apply(y.cwiseQuotient(unknown_scale())).col(0);
}

void CompressedBoundarySystem::solve_in_place(Matrix& rhs) const {
  system_.solve_in_place(rhs);  // A = A_s S^-1: y = S A_s^-1 b
  rhs = unknown_scale().asDiagonal() * rhs;
}

void CompressedBoundarySystem::solve_transposed_in_place(Matrix& rhs) const {
  rhs = unknown_scale().asDiagonal() * rhs;  // A^T x = b: A_s^T x = S b
  system_.solve_transposed_in_place(rhs);
}

double CompressedBoundarySystem::residual(const BoundarySolution& solution) const {
  const Index n = mesh_.node_count();
  Vector u(2 * n), p(2 * n);
  for (Index i = 0; i < n; ++i) {
    u.segment<2>(2 * i) = solution.displacement[i];
    p.segment<2>(2 * i) = solution.traction[i];
  }
  Matrix x(4 * n, 2);
  x.col(0) = influence_input(u, Vector::Zero(2 * n));
  x.col(1) = influence_input(Vector::Zero(2 * n), p);
  Matrix y = influence_.apply(x);
  for (Index i = 0; i < n; ++i) y.block<2, 1>(2 * i, 0) += diagonal_[i] * u.segment<2>(2 * i);
  for (Index i = 0; i < n; ++i)
    if (conditions_[i].on_axis) y.row(2 * i).setZero();  // degenerate, replaced in the system
  const Vector r = y.col(0) - y.col(1);
  const double scale = std::max(y.col(0).norm(), y.col(1).norm());
  return scale > 0.0 ? r.norm() / scale : r.norm();
}

double CompressedBoundarySystem::compression_ratio() const {
  const double n = 2.0 * static_cast<double>(mesh_.node_count());
  return static_cast<double>(influence_.stored_values() + system_.stored_values()) / (2.0 * n * n);
}

}  // namespace bemcontact::bem

namespace bemcontact::bem {

double compression_accuracy(const OperatorChoice& choice, const geometry::BoundaryMesh& mesh) {
  if (choice.accuracy > 0.0) return choice.accuracy;
  double smallest = mesh.scale;
  for (const auto& element : mesh.elements) smallest = std::min(smallest, element.length);
  const double size = mesh.scale > 0.0 ? mesh.scale : 1.0;
  return std::clamp(1e-6 * smallest / size, 1e-11, 1e-10);
}

const char* to_string(OperatorKind kind) {
  switch (kind) {
    case OperatorKind::automatic: return "auto";
    case OperatorKind::dense: return "dense";
    case OperatorKind::compressed: return "compressed";
  }
  return "?";
}

bool use_compressed_operator(const OperatorChoice& choice, Index unknowns, int symmetry_lines) {
  if (choice.kind == OperatorKind::compressed) return true;
  // Two perpendicular symmetry lines make hmat-oss's compression very slow (a quarter plate
  // with a hole, 13 200 unknowns: 380 s compressed against 19 s dense; README, Known
  // limitations): `auto` keeps such bodies dense.
  return choice.kind == OperatorKind::automatic && operators::hmatrix_available() && symmetry_lines < 2 &&
         unknowns >= OperatorChoice::automatic_threshold;
}

}  // namespace bemcontact::bem
