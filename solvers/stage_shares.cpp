#include "tide/solvers/stage_shares.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numeric>

namespace tide {

std::vector<int> stage_shares_permille(const std::vector<StageTime>& times) {
  std::vector<int> shares(times.size(), 0);
  const double total =
      std::accumulate(times.begin(), times.end(), 0.0, [](double sum, const StageTime& t) { return sum + t.seconds; });
  if (!(total > 0)) return shares;
  std::vector<double> remainders(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double exact = 1000 * times[k].seconds / total;
    shares[k] = static_cast<int>(std::floor(exact));
    remainders[k] = exact - shares[k];
  }
  // The tenths the rounding down left over go to the largest remainders (the first on a tie).
  std::vector<std::size_t> order(times.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return remainders[a] > remainders[b]; });
  const int missing = 1000 - std::accumulate(shares.begin(), shares.end(), 0);
  for (int k = 0; k < missing; ++k) ++shares[order[static_cast<std::size_t>(k)]];
  return shares;
}

std::string format_stage_shares(const std::vector<StageTime>& times) {
  const std::vector<int> shares = stage_shares_permille(times);
  std::string text;
  for (std::size_t k = 0; k < times.size(); ++k) {
    char share[32];
    std::snprintf(share, sizeof share, " %d.%d%%", shares[k] / 10, shares[k] % 10);
    if (k > 0) text += ", ";
    text.append(times[k].name);
    text += share;
  }
  return text;
}

}  // namespace tide
