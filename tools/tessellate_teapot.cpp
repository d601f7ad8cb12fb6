// tessellate_teapot: turns Newell's Bezier-patch teapot data into a welded, outward-facing, Y-up triangle OBJ.
//
// Usage: tessellate_teapot DATA.txt OUT.obj [--steps N]
//
// Input format (see the header comment of the data file): '#' starts a comment, blank lines are
// ignored; then a patch count, one line of 16 zero-based control point indices per patch (row-major
// 4x4), a control point count, and one "x y z" line per control point. Z is up in the data.
//
// Pipeline: evaluate every bicubic patch on an (N+1)x(N+1) grid -> weld coincident vertices (1e-6,
// quantised hash) -> drop degenerate triangles -> orient patches consistently across shared seams
// and make each connected surface face outwards (positive signed volume once its open boundary
// loops are capped) -> Z-up to Y-up, (x, y, z) -> (x, z, -y) -> centre the bounding box on the
// origin -> round to the 6 significant digits written, re-weld and re-check -> write atomically.
//
// Exit codes: 0 success, 1 cannot write the output, 2 bad usage or bad input data.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "tools/teapot_obj_writer.h"
#include "tools/teapot_orientation.h"
#include "tools/teapot_patch_data.h"
#include "tools/teapot_tessellation.h"
#include "tools/teapot_welding.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitWriteError = 1;
constexpr int kExitBadInput = 2;

constexpr int kMaxSteps = 200;                 // 32 patches x 200 x 200 x 2 = 2.56 M triangles

using namespace raster::tools;  // the stages (tools/teapot_*.h) and Vec3 (tools/vec3.h)

struct Options {
  std::string data_path, out_path;
  int steps = 10;
};

[[noreturn]] void usage_error(const std::string& msg) {
  std::cerr << "tessellate_teapot: " << msg << "\n"
            << "usage: tessellate_teapot DATA.txt OUT.obj [--steps N]   (N in [1, " << kMaxSteps << "], default 10)\n";
  std::exit(kExitBadInput);
}

Options parse_args(int argc, char** argv) {
  Options o;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    std::string value;
    if (a == "--steps") {
      if (i + 1 >= argc) usage_error("--steps needs a value");
      value = argv[++i];
    } else if (a.rfind("--steps=", 0) == 0) {
      value = a.substr(8);
    } else if (a == "-h" || a == "--help") {
      std::cout << "usage: tessellate_teapot DATA.txt OUT.obj [--steps N]   (N in [1, " << kMaxSteps << "], default 10)\n";
      std::exit(kExitOk);
    } else if (a.size() > 1 && a[0] == '-') {
      usage_error("unknown option " + a);
    } else {
      positional.push_back(a);
      continue;
    }
    auto n = parse_int(value);
    if (!n || *n < 1 || *n > kMaxSteps) usage_error("--steps must be an integer in [1, " + std::to_string(kMaxSteps) + "], got '" + value + "'");
    o.steps = static_cast<int>(*n);
  }
  if (positional.size() != 2) usage_error("expected DATA.txt and OUT.obj");
  o.data_path = positional[0];
  o.out_path = positional[1];
  return o;
}

int run(const Options& opt) {
  std::ifstream in(opt.data_path, std::ios::binary);
  if (!in) {
    std::cerr << "tessellate_teapot: " << opt.data_path << ": cannot open for reading\n";
    return kExitBadInput;
  }
  PatchData data;
  try {
    data = parse_data(in);
  } catch (const InputError& e) {
    std::cerr << "tessellate_teapot: " << opt.data_path;
    if (e.line > 0) std::cerr << ":" << e.line;
    std::cerr << ": " << e.message << "\n";
    return kExitBadInput;
  }
  note_unused_control_points(data);

  // 1 and 2. Evaluate, weld and triangulate every patch (tools/teapot_tessellation.h).
  const int n = opt.steps;
  const std::size_t npatch = data.patches.size();
  auto [verts, tris, tri_patch, dropped, diag, area_eps] = tessellate_patches(data, n);
  // 3. Orient the patches consistently and each surface outwards (tools/teapot_orientation.h).
  orient_patches(tris, tri_patch, npatch, verts, diag);

  // 4. Z-up -> Y-up, (x, y, z) -> (x, z, -y) (a rotation, so orientation is kept), then centre the
  //    bounding box of the referenced vertices on the origin.
  for (Vec3& v : verts) v = {v.x, v.z, -v.y};
  std::vector<char> referenced(verts.size(), 0);
  for (const Tri& t : tris)
    for (std::uint32_t i : t) referenced[i] = 1;
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < verts.size(); ++i)
    if (referenced[i]) {
      const Vec3& v = verts[i];
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  const Vec3 centre = 0.5 * (lo + hi);
  for (Vec3& v : verts) v = v - centre;

  // 5. Round to the text written, weld again and split bowtie vertices (tools/teapot_welding.h).
  WrittenMesh written = round_and_reweld(verts, tris, area_eps, dropped);
  const std::size_t split_vertices = split_bowtie_vertices(written);
  const std::vector<Vec3>& out_verts = written.verts;
  const std::vector<Tri>& out_tris = written.tris;

  // 6. Report on what will be written.
  lo = {1e300, 1e300, 1e300};
  hi = {-1e300, -1e300, -1e300};
  for (const Vec3& v : out_verts) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  double signed_volume = 0;
  std::size_t away = 0;
  // Mid-height point of the body's axis of revolution (the data's z axis, x = y = 0, before recentring).
  const Vec3 body_centre{-centre.x, 0.0, -centre.z};
  for (const Tri& t : out_tris) {
    const Vec3 a = out_verts[t[0]], b = out_verts[t[1]], c = out_verts[t[2]];
    signed_volume += dot(a, cross(b, c)) / 6.0;
    const Vec3 centroid = (1.0 / 3.0) * (a + b + c);
    if (dot(cross(b - a, c - a), centroid - body_centre) > 0) ++away;
  }
  const EdgeStats es = edge_stats(out_tris);
  std::cerr << "control points " << data.points.size() << ", patches " << npatch << ", steps " << n << "\n"
            << "vertices " << out_verts.size() << ", triangles " << out_tris.size() << " (" << dropped
            << " degenerate dropped of " << npatch * static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * 2 << ")\n"
            << "bbox min (" << fmt6(lo.x) << ", " << fmt6(lo.y) << ", " << fmt6(lo.z) << ") max (" << fmt6(hi.x)
            << ", " << fmt6(hi.y) << ", " << fmt6(hi.z) << ")\n"
            << "signed volume (whole mesh, origin at bbox centre) " << signed_volume << "\n"
            << "capped signed volume (every open loop closed by a fan) " << capped_signed_volume(out_verts, out_tris) << "\n"
            << "bowtie vertices split (surfaces touching at a single point): " << split_vertices << "\n"
            << "triangles facing away from the body's axis centre: " << away << " of " << out_tris.size() << "\n"
            << "edges " << es.edges << ": manifold " << es.manifold << ", boundary " << es.boundary
            << ", two-sided but misoriented " << es.misoriented << ", non-manifold " << es.nonmanifold << "\n";

  // 7. Write atomically (tools/teapot_obj_writer.h).
  if (!write_obj(opt.out_path, opt.data_path, npatch, data.points.size(), n, written)) return kExitWriteError;
  std::cout << "wrote " << opt.out_path << ": " << out_verts.size() << " vertices, " << out_tris.size() << " triangles\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse_args(argc, argv));
  } catch (const std::exception& e) {
    std::cerr << "tessellate_teapot: error: " << e.what() << "\n";
    return kExitWriteError;
  } catch (...) {
    std::cerr << "tessellate_teapot: unknown error\n";
    return kExitWriteError;
  }
}
