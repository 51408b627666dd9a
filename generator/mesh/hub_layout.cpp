#include "hub_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace arbor {

int hubSlots(std::size_t n) { return std::max(2, static_cast<int>(std::ceil(std::sqrt(4.0 / std::numbers::pi * static_cast<double>(n))))); }

double hubSpread(const std::vector<std::array<double, 2>>& points) {
  if (points.empty()) return 0.0;
  std::vector<double> radii;
  for (const auto& p : points) radii.push_back(std::max(std::abs(p[0]), std::abs(p[1])));
  std::sort(radii.begin(), radii.end());
  return radii[std::min(radii.size() - 1, static_cast<std::size_t>(0.9 * static_cast<double>(radii.size())))];
}

namespace {

// Strictly increasing slots (0..slots-1) for values sorted ascending, nearest to them in the least-squares sense:
// order kept, so that no two necks between them swap sides.
std::vector<int> monotoneSlots(const std::vector<double>& values, int slots) {
  const std::size_t k = values.size();
  constexpr double kFar = 1e300;
  // cost[i][s]: best for the first i + 1 values with value i at slot s.
  std::vector<std::vector<double>> cost(k, std::vector<double>(static_cast<std::size_t>(slots), kFar));
  std::vector<std::vector<int>> from(k, std::vector<int>(static_cast<std::size_t>(slots), -1));
  for (std::size_t i = 0; i < k; ++i) {
    double best = kFar;
    int bestSlot = -1;
    for (int s = 0; s < slots; ++s) {
      if (i > 0 && s > 0 && cost[i - 1][static_cast<std::size_t>(s - 1)] < best) {
        best = cost[i - 1][static_cast<std::size_t>(s - 1)];
        bestSlot = s - 1;
      }
      const double before = i == 0 ? 0.0 : best;
      if (before >= kFar) continue;
      const double d = values[i] - s;
      cost[i][static_cast<std::size_t>(s)] = before + d * d;
      from[i][static_cast<std::size_t>(s)] = bestSlot;
    }
  }
  std::vector<int> out(k, 0);
  int s = static_cast<int>(std::min_element(cost[k - 1].begin(), cost[k - 1].end()) - cost[k - 1].begin());
  for (std::size_t i = k; i-- > 0;) {
    out[i] = s;
    s = from[i][static_cast<std::size_t>(s)];
  }
  return out;
}

}  // namespace

HubLayout layOutHub(const std::vector<std::array<double, 2>>& wanted) {
  HubLayout out;
  out.slots = hubSlots(wanted.size());
  out.cell.assign(wanted.size(), {-1, -1});
  if (wanted.empty()) return out;
  // Nine in ten within the ports' span: the few widest-leaning trunks take the rim instead of spreading the rest.
  const double r90 = hubSpread(wanted);
  const double half = 0.5 * (out.slots - 1);
  const double scale = r90 > 0.0 ? half / r90 : 0.0;
  // Columns by x, then rows by y within each column: both orders kept, as far as a grid can keep them.
  std::vector<std::size_t> byX(wanted.size());
  std::iota(byX.begin(), byX.end(), 0);
  std::stable_sort(byX.begin(), byX.end(), [&](std::size_t a, std::size_t b) { return wanted[a][0] < wanted[b][0]; });
  const std::size_t n = wanted.size(), slots = static_cast<std::size_t>(out.slots);
  std::size_t next = 0;
  for (std::size_t column = 0; column < slots && next < n; ++column) {
    const std::size_t take = (n - next + (slots - column) - 1) / (slots - column);  // the rest spread evenly
    std::vector<std::size_t> members(byX.begin() + static_cast<std::ptrdiff_t>(next), byX.begin() + static_cast<std::ptrdiff_t>(next + take));
    next += take;
    std::stable_sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) { return wanted[a][1] < wanted[b][1]; });
    std::vector<double> ys;
    for (std::size_t m : members) ys.push_back(wanted[m][1] * scale + half);
    const std::vector<int> rows = monotoneSlots(ys, out.slots);
    for (std::size_t i = 0; i < members.size(); ++i) out.cell[members[i]] = {2 * static_cast<int>(column) + 1, 2 * rows[i] + 1};
  }
  return out;
}

}  // namespace arbor
