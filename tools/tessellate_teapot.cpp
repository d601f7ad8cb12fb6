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
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>

#include "tools/vec3.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitWriteError = 1;
constexpr int kExitBadInput = 2;

constexpr int kMaxSteps = 200;                 // 32 patches x 200 x 200 x 2 = 2.56 M triangles
constexpr long long kMaxPatches = 100000;
constexpr long long kMaxControlPoints = 10000000;
constexpr double kWeldTolerance = 1e-6;

using namespace raster::tools;  // Vec3 and its operations (tools/vec3.h)

using Tri = std::array<std::uint32_t, 3>;

struct PatchData {
  std::vector<std::array<std::uint32_t, 16>> patches;
  std::vector<int> patch_lines;  // source line of each patch, for error messages
  std::vector<Vec3> points;
};

// Thrown for bad input; main() turns it into "FILE:LINE: message" and exit code 2.
struct InputError {
  int line;  // 0 when no particular line applies
  std::string message;
};

// ---------------------------------------------------------------- parsing

std::vector<std::string_view> split_tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\v' || s[i] == '\f')) ++i;
    std::size_t j = i;
    while (j < s.size() && !(s[j] == ' ' || s[j] == '\t' || s[j] == '\r' || s[j] == '\v' || s[j] == '\f')) ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

std::string quoted(std::string_view tok) {
  std::string q = "'";
  for (char c : tok.substr(0, 40)) q += (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) ? '?' : c;
  if (tok.size() > 40) q += "...";
  return q + "'";
}

std::optional<long long> parse_int(std::string_view tok) {
  long long v = 0;
  auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc() || p != tok.data() + tok.size()) return std::nullopt;
  return v;
}

std::optional<double> parse_real(std::string_view tok) {
  if (tok.size() > 1 && tok[0] == '+' && tok[1] != '-' && tok[1] != '+') tok.remove_prefix(1);
  double v = 0;
  auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc() || p != tok.data() + tok.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// Reads the data lines (comments and blank lines removed) together with their line numbers.
class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}

  // Next line that has data; false at end of file.
  bool next(std::vector<std::string_view>& tokens, int& line_no) {
    while (std::getline(in_, buf_)) {
      ++line_;
      if (buf_.find('\0') != std::string::npos) throw InputError{line_, "contains a NUL byte (not a text file?)"};
      std::string_view s = buf_;
      if (auto hash = s.find('#'); hash != std::string_view::npos) s = s.substr(0, hash);
      tokens = split_tokens(s);
      if (!tokens.empty()) {
        line_no = line_;
        return true;
      }
    }
    if (in_.bad()) throw InputError{line_, "read error"};
    return false;
  }
  int line() const { return line_; }

 private:
  std::istream& in_;
  std::string buf_;
  int line_ = 0;
};

long long parse_count(LineReader& reader, const char* what, long long max_count) {
  std::vector<std::string_view> tok;
  int ln = 0;
  if (!reader.next(tok, ln)) throw InputError{reader.line(), std::string("unexpected end of file, expected the ") + what};
  if (tok.size() != 1) throw InputError{ln, std::string("expected the ") + what + " alone on the line, got " + std::to_string(tok.size()) + " fields"};
  auto v = parse_int(tok[0]);
  if (!v) throw InputError{ln, std::string("expected the ") + what + " (an integer), got " + quoted(tok[0])};
  if (*v < 1 || *v > max_count)
    throw InputError{ln, std::string(what) + " " + std::to_string(*v) + " out of range [1, " + std::to_string(max_count) + "]"};
  return *v;
}

PatchData parse_data(std::istream& in) {
  LineReader reader(in);
  PatchData d;
  std::vector<std::string_view> tok;
  int ln = 0;

  const long long npatches = parse_count(reader, "patch count", kMaxPatches);
  d.patches.reserve(static_cast<std::size_t>(npatches));
  for (long long p = 0; p < npatches; ++p) {
    if (!reader.next(tok, ln))
      throw InputError{reader.line(), "unexpected end of file: read " + std::to_string(p) + " of " + std::to_string(npatches) + " patches"};
    if (tok.size() != 16)
      throw InputError{ln, "patch " + std::to_string(p) + ": expected 16 control point indices, got " + std::to_string(tok.size()) + " fields"};
    std::array<std::uint32_t, 16> idx{};
    for (int k = 0; k < 16; ++k) {
      auto v = parse_int(tok[static_cast<std::size_t>(k)]);
      if (!v) throw InputError{ln, "patch " + std::to_string(p) + ": index " + std::to_string(k) + " is not an integer: " + quoted(tok[static_cast<std::size_t>(k)])};
      if (*v < 0 || *v >= kMaxControlPoints)
        throw InputError{ln, "patch " + std::to_string(p) + ": index " + std::to_string(*v) + " out of range (indices are zero-based)"};
      idx[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(*v);
    }
    d.patches.push_back(idx);
    d.patch_lines.push_back(ln);
  }

  const long long npoints = parse_count(reader, "control point count", kMaxControlPoints);
  d.points.reserve(static_cast<std::size_t>(std::min<long long>(npoints, 1 << 20)));
  for (long long i = 0; i < npoints; ++i) {
    if (!reader.next(tok, ln))
      throw InputError{reader.line(), "unexpected end of file: read " + std::to_string(i) + " of " + std::to_string(npoints) + " control points"};
    if (tok.size() != 3)
      throw InputError{ln, "control point " + std::to_string(i) + ": expected 3 coordinates \"x y z\", got " + std::to_string(tok.size()) + " fields"};
    double c[3];
    for (int k = 0; k < 3; ++k) {
      auto v = parse_real(tok[static_cast<std::size_t>(k)]);
      if (!v) throw InputError{ln, "control point " + std::to_string(i) + ": coordinate " + std::to_string(k) + " is not a finite number: " + quoted(tok[static_cast<std::size_t>(k)])};
      if (std::fabs(*v) > 1e9) throw InputError{ln, "control point " + std::to_string(i) + ": coordinate " + quoted(tok[static_cast<std::size_t>(k)]) + " is implausibly large"};
      c[k] = *v;
    }
    d.points.push_back({c[0], c[1], c[2]});
  }
  if (reader.next(tok, ln)) throw InputError{ln, "unexpected extra data after the " + std::to_string(npoints) + " control points: " + quoted(tok[0])};

  for (std::size_t p = 0; p < d.patches.size(); ++p)
    for (std::uint32_t idx : d.patches[p])
      if (idx >= d.points.size())
        throw InputError{d.patch_lines[p], "patch " + std::to_string(p) + ": control point index " + std::to_string(idx) + " >= control point count " + std::to_string(d.points.size())};
  return d;
}

// ---------------------------------------------------------------- geometry

std::array<double, 4> bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

// Welds points that lie within kWeldTolerance of an earlier point (quantised grid, 27-cell search).
class Welder {
 public:
  std::uint32_t add(Vec3 p) {
    const std::array<long long, 3> q = quantise(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(Key{q[0] + dx, q[1] + dy, q[2] + dz});
          if (it == cells_.end()) continue;
          for (std::uint32_t id : it->second)
            if (length(points_[id] - p) <= kWeldTolerance) return id;
        }
    const auto id = static_cast<std::uint32_t>(points_.size());
    points_.push_back(p);
    cells_[Key{q[0], q[1], q[2]}].push_back(id);
    return id;
  }
  const std::vector<Vec3>& points() const { return points_; }

 private:
  struct Key {
    long long x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (long long v : {k.x, k.y, k.z}) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  static std::array<long long, 3> quantise(Vec3 p) {
    return {std::llround(p.x / kWeldTolerance), std::llround(p.y / kWeldTolerance), std::llround(p.z / kWeldTolerance)};
  }
  std::vector<Vec3> points_;
  std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> cells_;
};

double tri_area(const std::vector<Vec3>& v, const Tri& t) {
  return 0.5 * length(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
}

bool degenerate(const std::vector<Vec3>& v, const Tri& t, double area_eps) {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || tri_area(v, t) <= area_eps;
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Signed volume (divergence theorem, origin-independent) of a triangle set after closing every open
// boundary loop with a fan to that loop's centroid. Positive means the triangles face outwards.
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

struct EdgeStats {
  std::size_t edges = 0, boundary = 0, manifold = 0, nonmanifold = 0, misoriented = 0;
};

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

std::string fmt6(double x) {
  if (std::fabs(x) < 1e-12) x = 0.0;  // no "-0" or "1e-17" noise from recentring
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// ---------------------------------------------------------------- main work

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
  {
    std::vector<char> used(data.points.size(), 0);
    for (const auto& p : data.patches)
      for (std::uint32_t i : p) used[i] = 1;
    std::string unused;
    std::size_t n_unused = 0;
    for (std::size_t i = 0; i < used.size(); ++i)
      if (!used[i]) {
        ++n_unused;
        if (n_unused <= 12) unused += " " + std::to_string(i);
      }
    if (n_unused) std::cerr << "note: " << n_unused << " control point(s) used by no patch:" << unused << (n_unused > 12 ? " ..." : "") << "\n";
  }

  // 1. Evaluate and weld (in the data's own Z-up frame; the later transform is exact).
  const int n = opt.steps;
  const std::size_t npatch = data.patches.size();
  Welder welder;
  std::vector<std::vector<std::uint32_t>> grid(npatch);  // (n+1)^2 welded ids, index a*(n+1)+b
  std::vector<std::array<double, 4>> basis(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) basis[static_cast<std::size_t>(i)] = bernstein(i == n ? 1.0 : static_cast<double>(i) / n);
  for (std::size_t p = 0; p < npatch; ++p) {
    const auto& idx = data.patches[p];
    grid[p].reserve(static_cast<std::size_t>((n + 1) * (n + 1)));
    for (int a = 0; a <= n; ++a)
      for (int b = 0; b <= n; ++b) {
        const auto& bu = basis[static_cast<std::size_t>(a)];  // along the rows (u)
        const auto& bv = basis[static_cast<std::size_t>(b)];  // along the columns (v)
        Vec3 s{};
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c)
            s = s + (bu[static_cast<std::size_t>(r)] * bv[static_cast<std::size_t>(c)]) * data.points[idx[static_cast<std::size_t>(4 * r + c)]];
        grid[p].push_back(welder.add(s));
      }
  }
  std::vector<Vec3> verts = welder.points();

  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Vec3& v : verts) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  const double diag = std::max(length(hi - lo), 1e-30);
  const double area_eps = 1e-14 * diag * diag;

  // 2. Triangles in each patch's natural (u,v) order: normal along dS/du x dS/dv. Drop degenerates.
  std::vector<Tri> tris;
  std::vector<std::uint32_t> tri_patch;
  std::size_t dropped = 0;
  const auto w = static_cast<std::size_t>(n) + 1;
  for (std::size_t p = 0; p < npatch; ++p)
    for (std::size_t a = 0; a < w - 1; ++a)
      for (std::size_t b = 0; b < w - 1; ++b) {
        const std::uint32_t v00 = grid[p][a * w + b], v10 = grid[p][(a + 1) * w + b];
        const std::uint32_t v11 = grid[p][(a + 1) * w + b + 1], v01 = grid[p][a * w + b + 1];
        for (const Tri& t : {Tri{v00, v10, v11}, Tri{v00, v11, v01}}) {
          if (degenerate(verts, t, area_eps)) {
            ++dropped;
            continue;
          }
          tris.push_back(t);
          tri_patch.push_back(static_cast<std::uint32_t>(p));
        }
      }

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

  // 4. Z-up -> Y-up, (x, y, z) -> (x, z, -y) (a rotation, so orientation is kept), then centre the
  //    bounding box of the referenced vertices on the origin.
  for (Vec3& v : verts) v = {v.x, v.z, -v.y};
  std::vector<char> referenced(verts.size(), 0);
  for (const Tri& t : tris)
    for (std::uint32_t i : t) referenced[i] = 1;
  lo = {1e300, 1e300, 1e300};
  hi = {-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < verts.size(); ++i)
    if (referenced[i]) {
      const Vec3& v = verts[i];
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  const Vec3 centre = 0.5 * (lo + hi);
  for (Vec3& v : verts) v = v - centre;

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

  // 7. Write atomically: OUT.tmp, then rename over OUT.
  const std::string tmp = opt.out_path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      std::cerr << "tessellate_teapot: " << tmp << ": cannot open for writing\n";
      return kExitWriteError;
    }
    const std::string source = std::filesystem::path(opt.data_path).filename().string();
    out << "# Utah teapot (Newell 1975) tessellated from the Bezier patches in " << source << " by tools/tessellate_teapot\n"
        << "# source: " << source << ", " << npatch << " bicubic patches, " << data.points.size() << " control points; steps " << n << " per patch side\n"
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
      return kExitWriteError;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, opt.out_path, ec);
  if (ec) {
    std::cerr << "tessellate_teapot: cannot rename " << tmp << " to " << opt.out_path << ": " << ec.message() << "\n";
    std::filesystem::remove(tmp, ec);
    return kExitWriteError;
  }
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
