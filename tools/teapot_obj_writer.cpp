// Writes the teapot OBJ: the header comments, "v" and "f" lines, through OUT.tmp and a rename.
#include "tools/teapot_obj_writer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include "tools/atomic_rename.h"

namespace raster::tools {

std::string fmt6(double x) {
  if (std::fabs(x) < 1e-12) x = 0.0;  // no "-0" or "1e-17" noise from recentring
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

bool write_obj(const std::string& out_path, const std::string& data_path, std::size_t npatch, std::size_t npoints,
               int steps, const WrittenMesh& mesh) {
  const std::vector<Vec3>& out_verts = mesh.verts;
  const std::vector<std::string>& out_text = mesh.text;
  const std::vector<Tri>& out_tris = mesh.tris;
  // 7. Write atomically: OUT.tmp, then rename over OUT.
  const std::string tmp = out_path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      std::cerr << "tessellate_teapot: " << tmp << ": cannot open for writing\n";
      return false;
    }
    const std::string source = std::filesystem::path(data_path).filename().string();
    out << "# Utah teapot (Newell 1975) tessellated from the Bezier patches in " << source << " by tools/tessellate_teapot\n"
        << "# source: " << source << ", " << npatch << " bicubic patches, " << npoints << " control points; steps " << steps << " per patch side\n"
        << "# vertices: " << out_verts.size() << ", triangles: " << out_tris.size() << "\n"
        << "# Y up, bounding box centred at the origin, counter-clockwise faces seen from outside, no normals\n"
        << "o teapot\n";
    for (const std::string& s : out_text) out << "v " << s << "\n";
    for (const Tri& t : out_tris) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    out.flush();
    if (!out) {
      std::cerr << "tessellate_teapot: " << tmp << ": write failed\n";
      out.close();
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      return false;
    }
  }
  return rename_over(tmp, out_path, "tessellate_teapot");
}

}  // namespace raster::tools
