// Re-welding the rounded teapot vertices by their text, and un-welding the vertices where surfaces only touch.
#include "tools/teapot_welding.h"

#include <cstdio>
#include <utility>

namespace raster::tools {

WrittenMesh round_and_reweld(const std::vector<Vec3>& verts, const std::vector<Tri>& tris, double area_eps,
                             std::size_t& dropped) {
  // 5. Round to what the file will hold, weld exact duplicates again, re-check degeneracy, compact.
  std::vector<std::string> text(verts.size());
  std::unordered_map<std::string, std::uint32_t> by_text;
  std::vector<std::uint32_t> remap(verts.size(), 0);
  std::vector<Vec3> out_verts;
  std::vector<std::string> out_text;
  std::vector<Tri> out_tris;
  std::vector<std::uint32_t> first_use(verts.size(), UINT32_MAX);
  for (const Tri& t : tris) {
    Tri r{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = t[static_cast<std::size_t>(k)];
      if (first_use[i] == UINT32_MAX) {
        const std::string s = fmt6(verts[i].x) + " " + fmt6(verts[i].y) + " " + fmt6(verts[i].z);
        auto [it, inserted] = by_text.try_emplace(s, static_cast<std::uint32_t>(out_verts.size()));
        if (inserted) {
          Vec3 q{};
          std::sscanf(s.c_str(), "%lf %lf %lf", &q.x, &q.y, &q.z);
          out_verts.push_back(q);
          out_text.push_back(s);
        }
        first_use[i] = it->second;
      }
      r[static_cast<std::size_t>(k)] = first_use[i];
    }
    if (degenerate(out_verts, r, area_eps)) {
      ++dropped;
      continue;
    }
    out_tris.push_back(r);
  }
  // Vertices referenced only by triangles dropped after rounding would be orphans: compact again.
  {
    std::vector<std::uint32_t> newid(out_verts.size(), UINT32_MAX);
    std::vector<Vec3> cv;
    std::vector<std::string> ct;
    for (Tri& t : out_tris)
      for (std::uint32_t& i : t) {
        if (newid[i] == UINT32_MAX) {
          newid[i] = static_cast<std::uint32_t>(cv.size());
          cv.push_back(out_verts[i]);
          ct.push_back(out_text[i]);
        }
        i = newid[i];
      }
    out_verts = std::move(cv);
    out_text = std::move(ct);
  }
  return {std::move(out_verts), std::move(out_text), std::move(out_tris)};
}

std::size_t split_bowtie_vertices(WrittenMesh& mesh) {
  std::vector<Vec3>& out_verts = mesh.verts;
  std::vector<std::string>& out_text = mesh.text;
  std::vector<Tri>& out_tris = mesh.tris;
  // 5b. Un-weld "bowtie" vertices: a vertex where surfaces that share no edge merely touch (in the
  //     Newell data the handle's lower end passes exactly through a vertex of the body) gets one copy
  //     per fan of triangles, so a loader averaging face normals does not blend unrelated surfaces.
  std::size_t split_vertices = 0;
  {
    std::vector<std::vector<std::uint32_t>> incident(out_verts.size());
    for (std::size_t i = 0; i < out_tris.size(); ++i)
      for (std::uint32_t v : out_tris[i]) incident[v].push_back(static_cast<std::uint32_t>(i));
    const std::size_t nv = out_verts.size();
    for (std::size_t v = 0; v < nv; ++v) {
      const auto& fs = incident[v];
      if (fs.size() < 2) continue;
      UnionFind fan(fs.size());
      std::unordered_map<std::uint32_t, std::size_t> via;  // other corner -> first local triangle using it
      for (std::size_t k = 0; k < fs.size(); ++k)
        for (std::uint32_t u : out_tris[fs[k]]) {
          if (u == v) continue;
          auto [it, inserted] = via.try_emplace(u, k);
          if (!inserted) fan.unite(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(it->second));
        }
      std::unordered_map<std::uint32_t, std::uint32_t> copy_of_fan;
      const std::uint32_t keep = fan.find(0);
      for (std::size_t k = 0; k < fs.size(); ++k) {
        const std::uint32_t root = fan.find(static_cast<std::uint32_t>(k));
        if (root == keep) continue;
        auto [it, inserted] = copy_of_fan.try_emplace(root, static_cast<std::uint32_t>(out_verts.size()));
        if (inserted) {
          out_verts.push_back(out_verts[v]);
          out_text.push_back(out_text[v]);
          ++split_vertices;
        }
        for (std::uint32_t& c : out_tris[fs[k]])
          if (c == v) c = it->second;
      }
    }
  }
  return split_vertices;
}

}  // namespace raster::tools
