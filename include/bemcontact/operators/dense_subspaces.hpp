#pragma once
// Subspaces of small dense matrices (rigid modes, constraints, coarse spaces): singular
// values, null spaces and column spaces. Kept in one translation unit because Eigen's SVD
// and pivoted QR are among the slowest templates to compile (about 40 s per file that
// instantiated them in the sanitizer build).
#include "bemcontact/core/types.hpp"

namespace bemcontact::operators {

// Singular values of `a`, largest first.
Vector singular_values(const Matrix& a);

// Singular values (largest first) and the full matrix V of right singular vectors of `a`.
struct RightSingularVectors {
  Vector values;
  Matrix V;
};
RightSingularVectors right_singular_vectors(const Matrix& a);

// Orthonormal basis (columns) of the null space of `a` (columns of V whose singular value
// is at most relative_tolerance * max(largest singular value, minimum_scale)); a matrix
// without rows has the whole space as null space.
Matrix null_space(const Matrix& a, double relative_tolerance, double minimum_scale = 0.0);

// Orthonormal basis (columns) of the span of `a`'s columns, by QR with column pivoting;
// columns whose pivot falls below `threshold` times the largest are dependent.
Matrix column_space(const Matrix& a, double threshold);

}  // namespace bemcontact::operators
