#include "patch_set.hpp"

#include <stdexcept>

namespace arbor {

namespace {

// Faces around each vertex, compressed: the faces of vertex v are face[first[v] .. first[v + 1]).
struct VertexFaces {
  std::vector<std::uint32_t> first, face;
  std::vector<std::uint8_t> corner;  // which corner of that face the vertex is

  explicit VertexFaces(const QuadMesh& mesh) {
    first.assign(mesh.vertexCount() + 1, 0);
    for (const auto& q : mesh.quads)
      for (std::uint32_t v : q) ++first[v + 1];
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) first[v + 1] += first[v];
    face.resize(first.back());
    corner.resize(first.back());
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t f = 0; f < mesh.quads.size(); ++f) {
      for (std::uint8_t k = 0; k < 4; ++k) {
        const std::uint32_t v = mesh.quads[f][k];
        face[fill[v]] = f;
        corner[fill[v]] = k;
        ++fill[v];
      }
    }
  }
};

// Every vertex's 1-ring once, counter-clockwise: for the k-th face around v (a, b, c after v) the ring holds
// a, b at [2k, 2k + 1], and c starts the next face's pair. A corner's ring is then a rotation of it.
struct VertexRings {
  std::vector<std::uint32_t> first;  // ring of v at ring[first[v] .. first[v + 1]), 2 n_v entries
  std::vector<std::uint32_t> ring;
  std::vector<std::uint32_t> faceAt; // faceAt[first[v] / 2 + k]... stored per pair: the k-th face around v
  std::vector<bool> closed;          // false on a boundary or a non-manifold fan

  VertexRings(const QuadMesh& mesh, const VertexFaces& vf) {
    const std::size_t n = mesh.vertexCount();
    first.assign(n + 1, 0);
    closed.assign(n, false);
    for (std::size_t v = 0; v < n; ++v) first[v + 1] = first[v] + 2 * (vf.first[v + 1] - vf.first[v]);
    ring.assign(first.back(), 0);
    faceAt.assign(first.back() / 2, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
      const std::uint32_t count = vf.first[v + 1] - vf.first[v];
      if (count == 0) continue;
      std::uint32_t k = vf.first[v];  // start with the first face listed; go counter-clockwise
      std::uint32_t f = vf.face[k];
      int j = vf.corner[k];
      std::uint32_t out = first[v];
      bool ok = true;
      for (std::uint32_t step = 0; step < count; ++step) {
        const auto& g = mesh.quads[f];
        ring[out] = g[static_cast<std::size_t>((j + 1) % 4)];
        ring[out + 1] = g[static_cast<std::size_t>((j + 2) % 4)];
        faceAt[out / 2] = f;
        out += 2;
        // The next face counter-clockwise about v holds the half-edge v -> (the vertex before v in g).
        const std::uint32_t last = g[static_cast<std::size_t>((j + 3) % 4)];
        std::uint32_t next = UINT32_MAX;
        for (std::uint32_t m = vf.first[v]; m < vf.first[v + 1]; ++m) {
          const auto& h = mesh.quads[vf.face[m]];
          if (h[static_cast<std::size_t>((vf.corner[m] + 1) % 4)] == last) {
            next = vf.face[m];
            j = vf.corner[m];
            break;
          }
        }
        if (next == UINT32_MAX) { ok = false; break; }
        f = next;
      }
      closed[v] = ok && f == vf.face[vf.first[v]];
    }
  }
};

// Where corner c's ring starts for face f: the index of f's pair in c's ring, or -1 on a boundary.
int ringStart(const VertexRings& vr, std::uint32_t f, std::uint32_t c) {
  if (!vr.closed[c]) return -1;
  const std::uint32_t begin = vr.first[c] / 2, pairs = (vr.first[c + 1] - vr.first[c]) / 2;
  for (std::uint32_t k = 0; k < pairs; ++k) {
    if (vr.faceAt[begin + k] == f) return static_cast<int>(2 * k);
  }
  return -1;
}

}  // namespace

PatchSet buildPatches(const QuadMesh& mesh) {
  const VertexFaces vf(mesh);
  const VertexRings vr(mesh, vf);
  PatchSet set;
  set.offset.reserve(mesh.quads.size() + 1);
  set.points.reserve(mesh.quads.size() * 17);
  set.valence.reserve(mesh.quads.size());
  set.prefix.reserve(mesh.quads.size());
  set.kind.reserve(mesh.quads.size());
  set.offset.push_back(0);

  for (std::uint32_t f = 0; f < mesh.quads.size(); ++f) {
    const auto& q = mesh.quads[f];
    std::array<std::uint8_t, 4> valence{};
    std::array<int, 4> start{};
    bool ok = true;
    int total = 0;
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t c = q[static_cast<std::size_t>(i)];
      start[static_cast<std::size_t>(i)] = ringStart(vr, f, c);
      ok = ok && start[static_cast<std::size_t>(i)] >= 0;
      const std::uint32_t n = (vr.first[c + 1] - vr.first[c]) / 2;
      valence[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(std::min<std::uint32_t>(n, 255));
      total += static_cast<int>(n);
    }
    const int count = 2 * total - 16;
    ok = ok && count <= kMaxPatchPoints;
    set.points.insert(set.points.end(), q.begin(), q.end());
    const std::size_t loopBegin = set.points.size();
    if (ok) {
      // The loop: corner 0's run, then each next corner's run without the two points it shares with the
      // previous one; the last two then repeat the first two (the loop closes) and are dropped.
      for (int i = 0; i < 4; ++i) {
        const std::uint32_t c = q[static_cast<std::size_t>(i)];
        const std::uint32_t* ring = vr.ring.data() + vr.first[c];
        const std::uint32_t size = vr.first[c + 1] - vr.first[c];
        const std::uint32_t from = static_cast<std::uint32_t>(start[static_cast<std::size_t>(i)]);
        for (std::uint32_t k = i == 0 ? 3 : 5; k < size; ++k) set.points.push_back(ring[(from + k) % size]);
      }
      const std::size_t end = set.points.size();
      ok = end - loopBegin >= 4 && static_cast<int>(end - loopBegin) == count - 2 &&
           set.points[end - 2] == set.points[loopBegin] && set.points[end - 1] == set.points[loopBegin + 1];
      set.points.resize(ok ? end - 2 : loopBegin);
    }
    set.valence.push_back(valence);
    if (ok) {
      std::array<std::uint8_t, 4> prefix{};
      int at = 0;
      for (int i = 0; i < 4; ++i) {
        prefix[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(at);
        at += 2 * valence[static_cast<std::size_t>(i)] - 5;
      }
      set.prefix.push_back(prefix);
      const bool regular = valence[0] == 4 && valence[1] == 4 && valence[2] == 4 && valence[3] == 4;
      set.kind.push_back(regular ? PatchKind::Regular : PatchKind::Extraordinary);
    } else {
      set.prefix.push_back({0, 0, 0, 0});
      set.kind.push_back(PatchKind::Fallback);  // drawn from its corners alone
    }
    set.offset.push_back(static_cast<std::uint32_t>(set.points.size()));
  }
  return set;
}

std::vector<std::uint32_t> cornerRing(const PatchSet& patches, std::size_t patch, int corner) {
  if (patches.kind[patch] == PatchKind::Fallback) throw std::invalid_argument("cornerRing: a fallback patch has no rings");
  const std::uint32_t* p = patches.pointsOf(patch);
  const std::size_t loopSize = patches.pointCount(patch) - 4;
  const int n = patches.valence[patch][static_cast<std::size_t>(corner)];
  std::vector<std::uint32_t> ring{p[(corner + 1) % 4], p[(corner + 2) % 4], p[(corner + 3) % 4]};
  for (int k = 0; k < 2 * n - 3; ++k) {
    ring.push_back(p[4 + (patches.prefix[patch][static_cast<std::size_t>(corner)] + static_cast<std::size_t>(k)) % loopSize]);
  }
  return ring;
}

std::array<std::uint32_t, 16> regularGrid(const PatchSet& patches, std::size_t patch) {
  if (patches.kind[patch] != PatchKind::Regular) throw std::invalid_argument("regularGrid: the patch is not regular");
  const std::uint32_t* p = patches.pointsOf(patch);
  // Grid position (column, row) of each loop point, counter-clockwise from the left of corner 3.
  static constexpr std::array<std::array<int, 2>, 12> kLoop{{{0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}, {3, 0},
                                                             {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}}};
  std::array<std::uint32_t, 16> grid{};
  grid[1 * 4 + 1] = p[0];
  grid[1 * 4 + 2] = p[1];
  grid[2 * 4 + 2] = p[2];
  grid[2 * 4 + 1] = p[3];
  for (std::size_t k = 0; k < 12; ++k) grid[static_cast<std::size_t>(kLoop[k][1] * 4 + kLoop[k][0])] = p[4 + k];
  return grid;
}

}  // namespace arbor
