// Orienting the teapot's patches: a flip parity over the seam graph, then each surface's capped signed volume.
#include "tools/teapot_orientation.h"

#include <cmath>
#include <iostream>
#include <string>
#include <unordered_map>
#include <utility>

namespace raster::tools {

void orient_patches(std::vector<Tri>& tris, const std::vector<std::uint32_t>& tri_patch, std::size_t npatch,
                    const std::vector<Vec3>& verts, double diag) {
  // 3a. Make neighbouring patches agree: across a seam edge shared by two patches the edge must be
  //     traversed in opposite directions. Propagate a flip parity over the patch adjacency graph.
  std::unordered_map<std::uint64_t, std::vector<std::pair<std::uint32_t, bool>>> edge_users;  // (patch, a<b)
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tris[i][static_cast<std::size_t>(k)], b = tris[i][static_cast<std::size_t>((k + 1) % 3)];
      edge_users[edge_key(a, b)].push_back({tri_patch[i], a < b});
    }
  std::vector<std::vector<std::pair<std::uint32_t, bool>>> adj(npatch);  // (neighbour, must differ)
  for (const auto& [key, users] : edge_users) {
    (void)key;
    if (users.size() != 2 || users[0].first == users[1].first) continue;
    const bool differ = users[0].second == users[1].second;  // same direction -> opposite flips
    adj[users[0].first].push_back({users[1].first, differ});
    adj[users[1].first].push_back({users[0].first, differ});
  }
  std::vector<int> flip(npatch, -1), component(npatch, -1);
  std::size_t conflicts = 0;
  int ncomp = 0;
  for (std::size_t s = 0; s < npatch; ++s) {
    if (flip[s] != -1) continue;
    std::vector<std::size_t> stack{s};
    flip[s] = 0;
    component[s] = ncomp;
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      for (auto [q, differ] : adj[p]) {
        const int want = flip[p] ^ (differ ? 1 : 0);
        if (flip[q] == -1) {
          flip[q] = want;
          component[q] = ncomp;
          stack.push_back(q);
        } else if (flip[q] != want) {
          ++conflicts;
        }
      }
    }
    ++ncomp;
  }
  if (conflicts) std::cerr << "warning: " << conflicts / 2 << " seam(s) could not be oriented consistently\n";

  // 3b. Each connected surface faces outwards: capped signed volume must be positive.
  auto oriented = [&](std::size_t i) {
    Tri t = tris[i];
    if (flip[tri_patch[i]]) std::swap(t[1], t[2]);
    return t;
  };
  //      A surface that encloses no volume (e.g. the flat handle quads at --steps 1) cannot tell; it
  //      follows the decision of the largest decided surface (the data is parameterised uniformly).
  std::vector<double> comp_volume(static_cast<std::size_t>(ncomp));
  double largest = 0;
  bool largest_inverted = false;
  for (int c = 0; c < ncomp; ++c) {
    std::vector<Tri> part;
    for (std::size_t i = 0; i < tris.size(); ++i)
      if (component[tri_patch[i]] == c) part.push_back(oriented(i));
    const double vol = capped_signed_volume(verts, part);
    comp_volume[static_cast<std::size_t>(c)] = vol;
    if (std::fabs(vol) > largest) {
      largest = std::fabs(vol);
      largest_inverted = vol < 0;
    }
  }
  const double volume_eps = 1e-9 * diag * diag * diag;
  for (int c = 0; c < ncomp; ++c) {
    const double vol = comp_volume[static_cast<std::size_t>(c)];
    const bool decided = std::fabs(vol) > volume_eps;
    const bool invert = decided ? vol < 0 : largest_inverted;
    std::string members;
    for (std::size_t p = 0; p < npatch; ++p)
      if (component[p] == c) {
        members += ' ';  // (not " " + to_string: GCC 12 warns falsely on that, -Wrestrict)
        members += std::to_string(p);
        if (invert) flip[p] ^= 1;
      }
    std::cerr << "surface " << c << " (patches" << members << "): capped volume " << std::fabs(vol)
              << (decided ? "" : " (encloses nothing: follows the largest surface)")
              << (invert ? ", inverted to face outwards" : "") << "\n";
  }
  std::string flipped;
  std::size_t nflipped = 0;
  for (std::size_t p = 0; p < npatch; ++p)
    if (flip[p]) {
      ++nflipped;
      flipped += ' ';
      flipped += std::to_string(p);
    }
  std::cerr << "patches reversed from their natural (u,v) order: " << nflipped << " of " << npatch
            << (nflipped ? ":" + flipped : std::string()) << "\n";
  for (std::size_t i = 0; i < tris.size(); ++i) tris[i] = oriented(i);
}

double capped_signed_volume(const std::vector<Vec3>& v, const std::vector<Tri>& tris) {
  std::unordered_map<std::uint64_t, int> use;  // +1 for a->b with a<b, -1 for the reverse
  std::unordered_map<std::uint64_t, int> count;
  for (const Tri& t : tris)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      use[edge_key(a, b)] += a < b ? 1 : -1;
      ++count[edge_key(a, b)];
    }
  Vec3 origin{};
  if (!tris.empty()) origin = v[tris[0][0]];
  auto vol = [&](Vec3 a, Vec3 b, Vec3 c) { return dot(a - origin, cross(b - origin, c - origin)) / 6.0; };
  double volume = 0;
  for (const Tri& t : tris) volume += vol(v[t[0]], v[t[1]], v[t[2]]);

  // Boundary edges (used once), directed as their triangle uses them.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary;
  for (const auto& [key, c] : count) {
    if (c != 1) continue;
    const auto lo = static_cast<std::uint32_t>(key >> 32), hi = static_cast<std::uint32_t>(key & 0xffffffffu);
    boundary.push_back(use[key] > 0 ? std::pair{lo, hi} : std::pair{hi, lo});
  }
  UnionFind uf(v.size());
  for (auto [a, b] : boundary) uf.unite(a, b);
  std::unordered_map<std::uint32_t, std::pair<Vec3, int>> centroid;  // loop root -> (sum, n)
  std::vector<char> seen(v.size(), 0);
  for (auto [a, b] : boundary)
    for (std::uint32_t x : {a, b})
      if (!seen[x]) {
        seen[x] = 1;
        auto& c = centroid[uf.find(x)];
        c.first = c.first + v[x];
        ++c.second;
      }
  for (auto [a, b] : boundary) {
    const auto& c = centroid[uf.find(a)];
    volume += vol(v[b], v[a], (1.0 / c.second) * c.first);  // cap triangle runs the edge backwards
  }
  return volume;
}

EdgeStats edge_stats(const std::vector<Tri>& tris) {
  std::unordered_map<std::uint64_t, std::pair<int, int>> e;  // (count, forward-minus-backward)
  for (const Tri& t : tris)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      auto& s = e[edge_key(a, b)];
      ++s.first;
      s.second += a < b ? 1 : -1;
    }
  EdgeStats st;
  st.edges = e.size();
  for (const auto& [key, s] : e) {
    (void)key;
    if (s.first == 1) ++st.boundary;
    else if (s.first == 2) (s.second == 0 ? st.manifold : st.misoriented)++;
    else ++st.nonmanifold;
  }
  return st;
}

}  // namespace raster::tools
