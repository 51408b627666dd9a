#include "hub_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>

#include "stem_capsules.hpp"

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

Vec3 HubNeck::at(double f) const {
  const double f2 = f * f, f3 = f2 * f;
  return from * (2 * f3 - 3 * f2 + 1) + t0 * (f3 - 2 * f2 + f) + to * (-2 * f3 + 3 * f2) + t1 * (f3 - f2);
}

Vec3 HubNeck::tangent(double f) const {
  const double f2 = f * f;
  return from * (6 * f2 - 6 * f) + t0 * (3 * f2 - 4 * f + 1) + to * (-6 * f2 + 6 * f) + t1 * (3 * f2 - 2 * f);
}

HubNeck hubNeck(const Vec3& from, const Vec3& normal, const Vec3& to, const Vec3& direction, double radius) {
  const double length = glm::distance(from, to);
  return HubNeck{from, normal * length, to, direction * length, std::clamp(static_cast<int>(length / (16.0 * radius)), 1, 16)};
}

namespace {

// The centres of a neck's cross sections, port first.
std::vector<Vec3> neckCentres(const HubNeck& n) {
  std::vector<Vec3> out{n.from};
  for (int k = 1; k <= n.steps; ++k) out.push_back(n.at(static_cast<double>(k) / n.steps));
  return out;
}

// A centre line, with its bounding box for a quick answer.
struct CentreLine {
  std::vector<Vec3> points;
  Vec3 lo{1e300}, hi{-1e300};
  explicit CentreLine(std::vector<Vec3> p = {}) : points(std::move(p)) {
    for (const Vec3& x : points) {
      lo = glm::min(lo, x);
      hi = glm::max(hi, x);
    }
  }
};

// The closest approach of two centre lines, or `within` where their boxes lie farther apart.
double lineDistance(const CentreLine& a, const CentreLine& b, double within) {
  const Vec3 gap = glm::max(a.lo - b.hi, b.lo - a.hi);
  if (gap.x > within || gap.y > within || gap.z > within) return within;
  double d = within;
  for (std::size_t i = 0; i + 1 < a.points.size(); ++i) {
    const Vec3 alo = glm::min(a.points[i], a.points[i + 1]), ahi = glm::max(a.points[i], a.points[i + 1]);
    for (std::size_t j = 0; j + 1 < b.points.size(); ++j) {
      const Vec3 far = glm::max(alo - glm::max(b.points[j], b.points[j + 1]), glm::min(b.points[j], b.points[j + 1]) - ahi);
      if (far.x >= d || far.y >= d || far.z >= d) continue;  // the segments' boxes already lie farther apart
      d = std::min(d, segmentDistance(a.points[i], a.points[i + 1], b.points[j], b.points[j + 1]));
    }
  }
  return d;
}

}  // namespace

void untangleHub(HubLayout& layout, const NeckFromCell& neck, const std::vector<double>& reach, const std::vector<std::vector<Vec3>>& tubes) {
  const std::size_t n = layout.cell.size();
  std::vector<CentreLine> tube;
  for (const auto& t : tubes) tube.emplace_back(t);
  std::vector<double> tubeDistance(n * n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a; b < n; ++b) tubeDistance[a * n + b] = tubeDistance[b * n + a] = lineDistance(tube[a], tube[b], reach[a] + reach[b]);
  auto lineFrom = [&](std::size_t t, const std::array<int, 2>& cell) { return CentreLine(neckCentres(neck(t, cell))); };
  // How much closer trunk a's neck (centre line na) and trunk b's (nb) come to each other or to the other's tube than
  // their surfaces' reach allows, or than the two tubes come (where the skeletons overlap past the necks, the necks
  // closing in on them is the skeletons' doing).
  std::size_t measured = 0;  // cuts worked out, against the budget below
  auto cutDepth = [&](std::size_t a, const CentreLine& na, std::size_t b, const CentreLine& nb) {
    ++measured;
    const double r = std::min(reach[a] + reach[b], tubeDistance[a * n + b]);
    const Vec3 gap = glm::max(glm::min(na.lo, tube[a].lo) - glm::max(nb.hi, tube[b].hi), glm::min(nb.lo, tube[b].lo) - glm::max(na.hi, tube[a].hi));
    if (gap.x >= r || gap.y >= r || gap.z >= r) return 0.0;  // trunk a's neck and tube lie apart from b's
    return r - std::min({lineDistance(na, nb, r), lineDistance(na, tube[b], r), lineDistance(tube[a], nb, r)});
  };
  std::vector<CentreLine> line;
  for (std::size_t t = 0; t < n; ++t) line.push_back(lineFrom(t, layout.cell[t]));
  // The cells' trunks (n: a free port cell; both odd).
  const int cells = 2 * layout.slots + 1;
  std::vector<std::size_t> at(static_cast<std::size_t>(cells * cells), n);
  auto trunkAt = [&](const std::array<int, 2>& c) -> std::size_t& { return at[static_cast<std::size_t>(c[1] * cells + c[0])]; };
  for (std::size_t t = 0; t < n; ++t) trunkAt(layout.cell[t]) = t;
  std::vector<double> cut(n * n, 0.0);  // between trunks' necks as they stand
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) cut[a * n + b] = cut[b * n + a] = cutDepth(a, line[a], b, line[b]);
  // Trunk t's cut with every other but `skip`, along centre line l.
  auto cutOf = [&](std::size_t t, const CentreLine& l, std::size_t skip) {
    double sum = 0.0;
    for (std::size_t u = 0; u < n; ++u)
      if (u != t && u != skip) sum += cutDepth(t, l, u, line[u]);
    return sum;
  };
  auto standingCut = [&](std::size_t t, std::size_t skip) {
    double sum = 0.0;
    for (std::size_t u = 0; u < n; ++u) sum += u == skip ? 0.0 : cut[t * n + u];
    return sum;
  };
  constexpr int kSweeps = 8;  // each takes the best move of every trunk that cuts another; a few settle it
  constexpr int kNear = 2;    // moves to port cells at most this many slots away: a neck's way changes little beyond
  // Moves are weighed until this many cuts have been worked out (wheat's 49 stalks take at most 104,000; a tuft of
  // 800 took 8 s without a bound); the layout is whole after every move.
  const std::size_t budget = measured + 2'000'000;
  for (int sweep = 0; sweep < kSweeps && measured < budget; ++sweep) {
    bool moved = false;
    for (std::size_t a = 0; a < n && measured < budget; ++a) {
      const double before = standingCut(a, n);
      if (before <= 0.0) continue;
      double best = 0.0;  // the change in the total cut
      std::array<int, 2> to{};
      CentreLine bestA, bestB;
      const auto [ci, cj] = layout.cell[a];
      for (int i = std::max(1, ci - 2 * kNear); i <= std::min(cells - 2, ci + 2 * kNear); i += 2) {
        for (int j = std::max(1, cj - 2 * kNear); j <= std::min(cells - 2, cj + 2 * kNear); j += 2) {
          const std::array<int, 2> cell{i, j};
          const std::size_t b = trunkAt(cell);
          if (b == a) continue;
          CentreLine la = lineFrom(a, cell);
          if (b == n) {
            const double change = cutOf(a, la, n) - before;
            if (change < best - 1e-12) std::tie(best, to, bestA) = std::tuple(change, cell, std::move(la));
            continue;
          }
          CentreLine lb = lineFrom(b, layout.cell[a]);
          const double after = cutOf(a, la, b) + cutOf(b, lb, a) + cutDepth(a, la, b, lb);
          const double change = after - before - standingCut(b, a);
          if (change < best - 1e-12) std::tie(best, to, bestA, bestB) = std::tuple(change, cell, std::move(la), std::move(lb));
        }
      }
      if (bestA.points.empty()) continue;
      moved = true;
      const std::size_t b = trunkAt(to);
      trunkAt(layout.cell[a]) = b;
      trunkAt(to) = a;
      if (b < n) {
        layout.cell[b] = layout.cell[a];
        line[b] = std::move(bestB);
      }
      layout.cell[a] = to;
      line[a] = std::move(bestA);
      for (const std::size_t t : {a, b}) {
        if (t == n) continue;
        for (std::size_t u = 0; u < n; ++u) cut[t * n + u] = cut[u * n + t] = u == t ? 0.0 : cutDepth(t, line[t], u, line[u]);
      }
    }
    if (!moved) break;
  }
}

}  // namespace arbor
