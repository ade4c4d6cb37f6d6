#pragma once
// The boundary element system A y = b of (II.12) on hierarchical matrices, for bodies too
// large for dense matrices. Nothing of size N^2 is formed:
//   - [H' | G] (H without its diagonal blocks, and G) is one compressed matrix: it gives the
//     diagonal blocks from exact fields (diagonal_blocks_from_exact_fields; in axisymmetry
//     with the radial expansion's traction integral, a compressed matrix of its own formed
//     and dropped during construction),
//     the right-hand side b = G p - H u of the prescribed values, and the residual;
//   - A, whose columns are those of H or -G by each unknown's kind in its node's frame,
//     plus the point constraints' rows and reaction columns (as in build_boundary_system),
//     is compressed and factored by H-LU.
// The entries of [H' | G] are integrated on demand (InfluenceBlocks), only for the blocks the
// adaptive cross approximation asks for; A reads its H and G from the compressed [H' | G].
// Both are compressed one component's rows at a time (HMatrixOptions::row_component).
#include <vector>

#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/bem/progress.hpp"
#include "bemcontact/operators/factorization.hpp"
#include "bemcontact/operators/hmatrix.hpp"
#include "bemcontact/operators/row_partitioned_hmatrix.hpp"

namespace bemcontact::bem {

// The accuracy a compressed operator of `mesh` is built to: the choice's, or automatically
// 1e-10, made smaller (down to 1e-11) by the smallest element's length against the body's
// size, 1e-6 h_min / L (a fine contact zone on a large body). Measured on a rigid cylinder
// on a block with 8 001 pairs (h_min / L = 1.4e-6): at 1e-10 the pressures carried a
// pair-to-pair noise of 7e-4 of the peak (0.6 % at 20 001 pairs), at 1e-11 of 4e-5, at
// 1e-12 of 6e-6. Near the entries' own quadrature accuracy the cross approximation stops
// converging and its blocks' ranks grow to their size: at 1e-12 some meshes took over 10
// minutes (20 001 pairs at 6e-13: over 20 minutes, against 98 s at 1e-10).
double compression_accuracy(const OperatorChoice& choice, const geometry::BoundaryMesh& mesh);

// H (zero on the diagonal node blocks) and G between a set of source nodes (rows) and a set
// of field nodes (columns), 2 x 2 per node pair, by integrating only the elements of the
// field nodes.
class InfluenceBlocks {
 public:
  InfluenceBlocks(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator);
  // H' and G between the nodes, the images of the elements folded in (assembly.hpp); H' has
  // no direct part on the diagonal blocks (they come from exact fields), their images' only.
  void evaluate(const std::vector<Index>& row_nodes, const std::vector<Index>& col_nodes, Matrix& H, Matrix& G) const;
  // int_e U p_e (2 rows per source node, one column per element) for the radial expansion's
  // traction p_e on each element (radial_expansion_traction; axisymmetry).
  Matrix radial_traction(const std::vector<Index>& row_nodes, const std::vector<Index>& elements) const;
  // X of assembly.hpp's image_translation_sums (2N x 2).
  Matrix image_translation_sums() const;

 private:
  const geometry::BoundaryMesh& mesh_;
  const ElementIntegrator& integrator_;
  std::vector<std::vector<Index>> node_elements_;
};

class CompressedBoundarySystem : public operators::Factorization {
 public:
  // Plane or axisymmetric. `what` names the system in messages. Progress phases:
  // "assembly of H and G", in axisymmetry "diagonal blocks" (the radial expansion's
  // traction integrals), "system assembly"; factorize: "H-LU factorisation".
  CompressedBoundarySystem(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                           std::vector<NodeCondition> conditions, std::vector<ConstraintEquation> constraints,
                           const operators::HMatrixOptions& options, const std::string& what,
                           const ProgressCallback& progress = {});

  Index size() const override { return system_.rows(); }
  const Vector& rhs() const { return rhs_; }
  // First 2N rows of the reaction columns (for rigid_mode_consistent_solution).
  Matrix reaction_columns() const;

  void factorize(bool keep_transposed = false, const ProgressCallback& progress = {});
  // A y (before factorize) and the solves with A and A^T (after), in place, in the
  // unknowns' own units.
  Vector apply(const Vector& y) const;
  void solve_in_place(Matrix& rhs) const override;
  void solve_transposed_in_place(Matrix& rhs) const override;
  // G P - H U (2N rows) for boundary values in global components, one set per column.
  Matrix boundary_rhs(const Matrix& U, const Matrix& P) const;
  // || H u - G p || / max(|| G p ||, || H u ||), as boundary_equation_residual.
  double residual(const BoundarySolution& solution) const;

  // Stored values of both compressed matrices over the 2 x (2N)^2 of dense H and G.
  double compression_ratio() const;

 private:
  // H U - G P through [H' | G] and the diagonal blocks (global components, per column).
  Matrix apply_h_minus_g(const Matrix& U, const Matrix& P) const;

  // Columns are stored scaled, so that every column weighs alike in a block's relative
  // accuracy: a node's columns divided by the length of its elements (an integral over a
  // small element is small; unscaled, its relative error grows with the grading, and the
  // boundary stress, a derivative over that element, with it), traction columns (G) times
  // the shear modulus (H is dimensionless). Measured on a plate with a hole graded 40:1, the
  // residual was 1000 times the accuracy without the length scaling.
  Vector unknown_scale() const;
  // [u; p] in the stored columns' units.
  Vector influence_input(const Vector& u, const Vector& p) const;

  const geometry::BoundaryMesh& mesh_;
  double traction_scale_;
  Vector node_scale_;  // 1 / (length of the node's elements)
  std::vector<NodeCondition> conditions_;
  std::vector<ConstraintEquation> constraints_;
  AnalysisType type_;
  InfluenceBlocks blocks_;
  std::vector<int> node_line_;  // the straight line each node's elements lie on (-1: none)
  operators::RowPartitionedHMatrix influence_;  // [H' | G]: applied only, so in row pieces
  std::vector<Mat2> diagonal_;    // H_ii
  operators::HMatrix system_;     // A
  Vector rhs_;

  operators::RowPartitionedHMatrix assemble_influence(const operators::HMatrixOptions& options, const std::string& what,
                                                      const ProgressCallback& progress);
  void influence_blocks(const std::vector<Index>& row_nodes, const std::vector<Index>& col_nodes, Matrix& H,
                        Matrix& G) const;
  std::vector<Mat2> diagonal_blocks(const operators::HMatrixOptions& options, const std::string& what,
                                    const ProgressCallback& progress) const;
  Vector radial_traction_integral(const operators::HMatrixOptions& options, const std::string& what,
                                  const ProgressCallback& progress) const;
  operators::HMatrix assemble_system(const operators::HMatrixOptions& options, const std::string& what,
                                     const ProgressCallback& progress) const;
  Vector prescribed_rhs() const;
};

}  // namespace bemcontact::bem
