#pragma once
// One interface for a factored square system, dense (DenseLU) or compressed (the H-LU of
// bem::CompressedBoundarySystem): what a solver needs of it once it is factored.
#include <limits>

#include "bemcontact/core/types.hpp"

namespace bemcontact::operators {

class Factorization {
 public:
  virtual ~Factorization() = default;
  virtual Index size() const = 0;
  // A x = b and A^T x = b for every column of `rhs`, in place.
  virtual void solve_in_place(Matrix& rhs) const = 0;
  virtual void solve_transposed_in_place(Matrix& rhs) const = 0;
  // The reciprocal condition number's estimate; NaN where none is made (an H-LU).
  virtual double reciprocal_condition() const { return std::numeric_limits<double>::quiet_NaN(); }
};

}  // namespace bemcontact::operators
