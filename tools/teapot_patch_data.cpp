// Reads Newell's patch data: tokens, comments and blank lines, counts and their limits, and every error's line.
#include "tools/teapot_patch_data.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <system_error>

namespace raster::tools {

namespace {

constexpr long long kMaxPatches = 100000;
constexpr long long kMaxControlPoints = 10000000;

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

}  // namespace

std::optional<long long> parse_int(std::string_view tok) {
  long long v = 0;
  auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc() || p != tok.data() + tok.size()) return std::nullopt;
  return v;
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

void note_unused_control_points(const PatchData& data) {
  std::vector<char> used(data.points.size(), 0);
  for (const auto& p : data.patches)
    for (std::uint32_t i : p) used[i] = 1;
  std::string unused;
  std::size_t n_unused = 0;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (!used[i]) {
      ++n_unused;
      if (n_unused > 12) continue;
      unused += ' ';  // (not " " + to_string: GCC 12 warns falsely on that here, -Wrestrict)
      unused += std::to_string(i);
    }
  if (n_unused) std::cerr << "note: " << n_unused << " control point(s) used by no patch:" << unused << (n_unused > 12 ? " ..." : "") << "\n";
}

}  // namespace raster::tools
