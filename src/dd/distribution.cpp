#include "bemcontact/dd/distribution.hpp"

#include <algorithm>
#include <numeric>

namespace bemcontact::dd {

std::vector<int> assign_subdomains(const std::vector<double>& costs, int processes) {
  std::vector<int> owner(costs.size(), 0);
  if (processes <= 1) return owner;
  std::vector<std::size_t> order(costs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
  std::vector<double> load(static_cast<std::size_t>(processes), 0.0);
  for (const std::size_t s : order) {
    const auto least = std::min_element(load.begin(), load.end());
    owner[s] = static_cast<int>(least - load.begin());
    *least += costs[s];
  }
  return owner;
}

}  // namespace bemcontact::dd
