#pragma once
// A small linear-operator interface: solvers (GMRES, contact) act on operators, not on
// meshes, so a dense, PETSc or hierarchical-matrix implementation can stand behind it.
#include "bemcontact/core/types.hpp"

namespace bemcontact::operators {

class LinearOperator {
 public:
  virtual ~LinearOperator() = default;
  virtual Index rows() const = 0;
  virtual Index cols() const = 0;
  // y = A x
  virtual void apply(const Vector& x, Vector& y) const = 0;
};

}  // namespace bemcontact::operators
