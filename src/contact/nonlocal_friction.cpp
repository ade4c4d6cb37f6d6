#include "bemcontact/contact/nonlocal_friction.hpp"

#include <cmath>

namespace bemcontact::contact {

double mollifier_bump(double distance, double radius) {
  const double t = distance / radius;
  return std::abs(t) < 1.0 ? std::exp(-1.0 / (1.0 - t * t)) : 0.0;
}

void add_mollifier_rows(const std::vector<ContactPair>& pairs, Index first, Index last, double radius,
                        MollifierRows& rows) {
  rows.resize(pairs.size());
  std::vector<double> s(static_cast<std::size_t>(last - first), 0.0);
  for (Index i = first + 1; i < last; ++i)
    s[static_cast<std::size_t>(i - first)] =
        s[static_cast<std::size_t>(i - first - 1)] + (pairs[i].position1 - pairs[i - 1].position1).norm();
  for (Index i = first; i < last; ++i) {
    auto& row = rows[static_cast<std::size_t>(i)];
    row.clear();
    double total = 0.0;
    for (Index j = first; j < last; ++j) {
      const double value = mollifier_bump(s[static_cast<std::size_t>(j - first)] - s[static_cast<std::size_t>(i - first)],
                                          radius) * pairs[j].weight;
      if (value > 0.0) row.emplace_back(j, value), total += value;
    }
    for (auto& entry : row) entry.second /= total;
  }
}

}  // namespace bemcontact::contact
