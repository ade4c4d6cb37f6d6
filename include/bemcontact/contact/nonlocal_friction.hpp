#pragma once
// The non-local Coulomb law of Oden and Pires [OdenPires1983] (the thesis' section V.5.1
// uses a law of this type): the slip threshold of a pair is beta times the mollified normal
// traction, g_i = beta (omega_rho * |p_n|)_i, instead of beta |p_n|_i. omega_rho is the C-infinity
// bump of radius rho along the contact boundary,
//   omega(r) = exp(-1 / (1 - (r / rho)^2)) for |r| < rho, 0 beyond,
// normalised to unit integral over the contact's pairs with their quadrature weights:
//   (omega * p)_i = sum_j W_ij p_j,   W_ij = omega(s_i - s_j) w_j / sum_k omega(s_i - s_k) w_k,
// s the arc length along side 1's zone (the distance from pair to pair) and w the pairs'
// weights. Renormalised over the contact, a uniform pressure passes unchanged and no
// traction leaks past the zone's ends (a kernel of unit integral on the whole line would
// lose up to half of it there; that convention moves c/a by a few hundredths).
#include <utility>
#include <vector>

#include "bemcontact/contact/pairing.hpp"

namespace bemcontact::contact {

// Per pair, its row of W as (pair, weight); a local pair's row is empty.
using MollifierRows = std::vector<std::vector<std::pair<Index, double>>>;

double mollifier_bump(double distance, double radius);

// sum_j W_ij measure(j) over one row of W: a pair's mollified |p_n| (or any pairwise measure).
template <class Measure>
double mollified(const std::vector<std::pair<Index, double>>& row, const Measure& measure) {
  double sum = 0.0;
  for (const auto& [j, weight] : row) sum += weight * measure(j);
  return sum;
}

// The rows of the pairs [first, last) (one contact, in the zone's order) for the radius rho.
void add_mollifier_rows(const std::vector<ContactPair>& pairs, Index first, Index last, double radius,
                        MollifierRows& rows);

}  // namespace bemcontact::contact
