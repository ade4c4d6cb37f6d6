#pragma once
// Gauss quadrature rules (section II.4.4.1), computed once per order and cached.
//
//   gauss_legendre(n): nodes x_i in (-1, 1), weights w_i with
//       sum_i w_i f(x_i) = int_{-1}^{1} f(x) dx   for every polynomial f of degree <= 2n - 1.
//   gauss_log(n):      nodes t_i in (0, 1), weights w_i with
//       sum_i w_i f(t_i) = int_0^1 f(t) ln(1/t) dt  for every polynomial f of degree <= 2n - 1.
//
// The returned references stay valid for the life of the program; every function here is
// safe to call from several threads at once.
#include <vector>

namespace bemcontact::quadrature {

struct Rule {
  std::vector<double> nodes;
  std::vector<double> weights;
  int size() const { return static_cast<int>(nodes.size()); }
};

// n >= 1. Nodes in increasing order.
const Rule& gauss_legendre(int n);

// n >= 1. Nodes in increasing order.
const Rule& gauss_log(int n);

}  // namespace bemcontact::quadrature
