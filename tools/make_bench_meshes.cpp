// make_bench_meshes: writes the benchmark meshes (icosphere, organic scanned-like blob, stacked occluding layers)
// as deterministic binary little-endian PLY files with per-vertex normals.
//
// Usage: make_bench_meshes OUT_DIR
//
// Writes OUT_DIR/icosphere.ply, OUT_DIR/organic.ply and OUT_DIR/occlusion.ply, each atomically (OUT.tmp, then
// renamed). Every mesh is closed or single-sided as described below, counter-clockwise seen from the side its
// normals point to (raster's and OpenGL's front faces). The output is byte-identical on every run: the only
// randomness is a fixed-seed SplitMix64 stream, and every number is computed in double and rounded once to float.
//
// Exit codes: 0 success, 1 a mesh failed its checks or an output could not be written, 2 bad usage.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "tools/vec3.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitWriteError = 1;
constexpr int kExitUsage = 2;

constexpr double kPi = 3.14159265358979323846;

// ------------------------------------------------------------------------------------------------ vectors

using namespace raster::tools;  // Vec3 and its operations (tools/vec3.h)

// ------------------------------------------------------------------------------------------------ meshes

using Triangle = std::array<uint32_t, 3>;

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // one per position, unit
    std::vector<Triangle> triangles;

    uint32_t add_vertex(Vec3 position, Vec3 normal = {}) {
        positions.push_back(position);
        normals.push_back(normal);
        return static_cast<uint32_t>(positions.size() - 1);
    }
};

Vec3 face_normal(const Mesh& mesh, const Triangle& t) {
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    return cross(b - a, c - a);  // length = twice the area
}

// Area-weighted mean of the normals of the faces around each vertex, normalised.
void set_area_weighted_normals(Mesh& mesh) {
    std::fill(mesh.normals.begin(), mesh.normals.end(), Vec3{});
    for (const Triangle& t : mesh.triangles) {
        const Vec3 n = face_normal(mesh, t);
        for (uint32_t corner : t) mesh.normals[corner] = mesh.normals[corner] + n;
    }
    for (Vec3& n : mesh.normals) n = normalized(n);
}

// What every mesh must satisfy before it is written; prints the summary line and returns false on a defect.
// `outward` is the direction each face is expected to face at its centroid (e.g. away from the centre).
template <typename OutwardFn>
bool check_mesh(const char* name, const Mesh& mesh, OutwardFn outward) {
    size_t inward = 0, degenerate = 0, bad_normals = 0;
    double min_area = INFINITY, max_area = 0;
    for (const Triangle& t : mesh.triangles) {
        const Vec3 n = face_normal(mesh, t);
        const double area = 0.5 * length(n);
        if (!(area > 0)) ++degenerate;
        min_area = std::min(min_area, area);
        max_area = std::max(max_area, area);
        const Vec3 centroid = (1.0 / 3.0) * (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]);
        if (dot(n, outward(centroid)) <= 0) ++inward;
    }
    for (const Vec3& n : mesh.normals) bad_normals += !(std::abs(length(n) - 1.0) < 1e-6);
    std::cerr << name << ": " << mesh.positions.size() << " vertices, " << mesh.triangles.size()
              << " triangles, triangle area " << min_area << " .. " << max_area << " (ratio "
              << (min_area > 0 ? max_area / min_area : INFINITY) << "), facing the wrong way " << inward
              << ", degenerate " << degenerate << ", non-unit normals " << bad_normals << "\n";
    return inward == 0 && degenerate == 0 && bad_normals == 0;
}

// ------------------------------------------------------------------------------------------------ icosphere

// The icosahedron (12 vertices on the unit sphere), each of its 20 faces subdivided into 4 `subdivisions` times,
// new vertices projected onto the sphere. Normals are the positions (unit radius).
Mesh make_icosphere(int subdivisions) {
    Mesh mesh;
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    const Vec3 corners[12] = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (const Vec3& c : corners) mesh.add_vertex(normalized(c), normalized(c));
    std::vector<Triangle> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    // The icosahedron is convex around the origin: a face is counter-clockwise from outside when its normal
    // points away from the origin. Subdivision keeps each face's winding.
    for (Triangle& f : faces)
        if (dot(cross(mesh.positions[f[1]] - mesh.positions[f[0]], mesh.positions[f[2]] - mesh.positions[f[0]]),
                mesh.positions[f[0]]) < 0)
            std::swap(f[1], f[2]);

    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint_of_edge;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const std::pair<uint32_t, uint32_t> key = std::minmax(a, b);
            if (auto it = midpoint_of_edge.find(key); it != midpoint_of_edge.end()) return it->second;
            const Vec3 p = normalized(mesh.positions[a] + mesh.positions[b]);
            const uint32_t id = mesh.add_vertex(p, p);
            midpoint_of_edge.emplace(key, id);
            return id;
        };
        std::vector<Triangle> finer;
        finer.reserve(faces.size() * 4);
        for (const Triangle& f : faces) {
            const uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
        }
        faces = std::move(finer);
    }
    mesh.triangles = std::move(faces);
    return mesh;
}

// ------------------------------------------------------------------------------------------------ noise

// SplitMix64: a fixed, portable pseudo-random stream (std's distributions are not portable across libraries).
class SplitMix64 {
public:
    explicit SplitMix64(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1) from the top 53 bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    uint64_t state_;
};

// Perlin's improved gradient noise in 3D, with a permutation shuffled from a fixed seed: smooth, values in about
// [-1, 1], zero at integer lattice points.
class GradientNoise {
public:
    explicit GradientNoise(uint64_t seed) {
        std::array<uint8_t, 256> permutation;
        std::iota(permutation.begin(), permutation.end(), uint8_t{0});
        SplitMix64 random(seed);
        for (size_t i = permutation.size() - 1; i > 0; --i) std::swap(permutation[i], permutation[random.next() % (i + 1)]);
        for (size_t i = 0; i < 512; ++i) table_[i] = permutation[i & 255];
    }

    double operator()(Vec3 p) const {
        const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
        const int X = static_cast<int>(fx) & 255, Y = static_cast<int>(fy) & 255, Z = static_cast<int>(fz) & 255;
        const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
        const double u = fade(x), v = fade(y), w = fade(z);
        const int A = table_[X] + Y, AA = table_[A] + Z, AB = table_[A + 1] + Z;
        const int B = table_[X + 1] + Y, BA = table_[B] + Z, BB = table_[B + 1] + Z;
        return lerp(w,
                    lerp(v, lerp(u, grad(table_[AA], x, y, z), grad(table_[BA], x - 1, y, z)),
                         lerp(u, grad(table_[AB], x, y - 1, z), grad(table_[BB], x - 1, y - 1, z))),
                    lerp(v, lerp(u, grad(table_[AA + 1], x, y, z - 1), grad(table_[BA + 1], x - 1, y, z - 1)),
                         lerp(u, grad(table_[AB + 1], x, y - 1, z - 1), grad(table_[BB + 1], x - 1, y - 1, z - 1))));
    }

    // Fractal sum of `octaves` noises, each at twice the frequency and half the amplitude of the previous one.
    double fractal(Vec3 p, int octaves) const {
        double sum = 0, amplitude = 1;
        for (int i = 0; i < octaves; ++i) {
            sum += amplitude * (*this)(p);
            p = 2.0 * p;
            amplitude *= 0.5;
        }
        return sum;
    }

private:
    static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
    static double lerp(double t, double a, double b) { return a + t * (b - a); }
    static double grad(int hash, double x, double y, double z) {
        const int h = hash & 15;
        const double u = h < 8 ? x : y;
        const double v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
        return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
    }

    std::array<int, 512> table_{};
};

// ------------------------------------------------------------------------------------------------ organic blob

// A lumpy, potato-like closed surface in the style of a 3D scan: a cube sphere (every cube face an N x N grid,
// projected onto the sphere, so cells near the cube's corners are smaller), each vertex jittered along the sphere
// and pushed in or out by a multi-octave noise of its direction, stretched unevenly. Quads split along their
// shorter diagonal, as a remesher would. The surface is star-shaped around the origin.
struct OrganicParams {
    int cells_per_face_side = 80;     // 6 * 80 * 80 * 2 = 76,800 triangles
    uint64_t seed = 20240607;         // the noise's and the jitter's fixed seed
    double jitter = 0.35;             // tangential jitter, in cells
    double lump_amplitude = 0.32;     // radial displacement of the coarsest octave
    double lump_frequency = 1.1;      // of the coarsest octave, per unit of direction
    int octaves = 5;                  // the finest spans about three cells
    Vec3 stretch{1.25, 0.95, 1.0};    // uneven scale: an elongated blob
};

Mesh make_organic(const OrganicParams& params) {
    const int n = params.cells_per_face_side;
    const GradientNoise noise(params.seed);
    const double cell_angle = (kPi / 2.0) / n;  // a cell's side at a face's centre, in radians

    // The cube's surface lattice: integer points (i, j, k) in [0, n]^3 with a coordinate at 0 or n. A point on a
    // seam belongs to several faces; the map gives it one vertex, and its jitter is a function of the point alone.
    std::map<std::array<int, 3>, uint32_t> vertex_of_lattice_point;
    Mesh mesh;
    auto vertex = [&](std::array<int, 3> lattice) {
        if (auto it = vertex_of_lattice_point.find(lattice); it != vertex_of_lattice_point.end()) return it->second;
        const Vec3 on_cube{2.0 * lattice[0] / n - 1.0, 2.0 * lattice[1] / n - 1.0, 2.0 * lattice[2] / n - 1.0};
        Vec3 direction = normalized(on_cube);
        // Jitter along the sphere: two tangent directions, offsets from a stream seeded by the lattice point.
        SplitMix64 random(params.seed ^ (uint64_t(lattice[0]) << 42) ^ (uint64_t(lattice[1]) << 21) ^
                          uint64_t(lattice[2]));
        const Vec3 helper = std::abs(direction.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
        const Vec3 tangent_u = normalized(cross(helper, direction)), tangent_v = cross(direction, tangent_u);
        // A cell's side on the sphere shrinks about as 1 / |on_cube|^2 from a face's centre to its corners.
        const double local_cell = cell_angle / dot(on_cube, on_cube);
        const double du = (random.uniform() * 2 - 1) * params.jitter * local_cell;
        const double dv = (random.uniform() * 2 - 1) * params.jitter * local_cell;
        direction = normalized(direction + du * tangent_u + dv * tangent_v);
        const double radius =
            1.0 + params.lump_amplitude * noise.fractal(params.lump_frequency * direction + Vec3{0.37, 1.91, 2.53},
                                                        params.octaves);
        const Vec3 p = radius * direction;
        const uint32_t id =
            mesh.add_vertex({p.x * params.stretch.x, p.y * params.stretch.y, p.z * params.stretch.z});
        vertex_of_lattice_point.emplace(lattice, id);
        return id;
    };

    // Face (axis, sign): the lattice coordinate `axis` is fixed at 0 or n; grid steps (a, b) run along
    // axis + 1 and axis + 2 (the latter reversed on the negative faces), so that a x b points outwards and the
    // grid's quads, taken a then b, are counter-clockwise seen from outside.
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {+1, -1})
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) {
                    auto corner = [&](int da, int db) {
                        std::array<int, 3> lattice{};
                        lattice[axis] = sign > 0 ? n : 0;
                        lattice[(axis + 1) % 3] = a + da;
                        lattice[(axis + 2) % 3] = sign > 0 ? b + db : n - (b + db);
                        return vertex(lattice);
                    };
                    const uint32_t v00 = corner(0, 0), v10 = corner(1, 0), v11 = corner(1, 1), v01 = corner(0, 1);
                    const double diagonal_00_11 = length(mesh.positions[v11] - mesh.positions[v00]);
                    const double diagonal_10_01 = length(mesh.positions[v01] - mesh.positions[v10]);
                    if (diagonal_00_11 <= diagonal_10_01)
                        mesh.triangles.insert(mesh.triangles.end(), {{v00, v10, v11}, {v00, v11, v01}});
                    else
                        mesh.triangles.insert(mesh.triangles.end(), {{v00, v10, v01}, {v10, v11, v01}});
                }
    set_area_weighted_normals(mesh);
    return mesh;
}

// ------------------------------------------------------------------------------------------------ occlusion

// Stacked wavy sheets facing a camera at the origin looking down -z: layer k (0 nearest) lies around view
// distance first_distance + k * spacing and is sized to cover the whole field of view there (with a margin), so
// every pixel sees every layer. The sheets are written nearest first: drawn in file order, every layer after the
// first is hidden everywhere, the case hierarchical Z exists for (31 of 32 layers culled block by block); with
// farthest_first each layer would be nearer than all before it and nothing could be culled.
struct OcclusionParams {
    int layers = 32;
    int cells_per_side = 32;             // 32 * 32 * 2 = 2,048 triangles a layer
    double first_distance = 2.0;
    double spacing = 0.25;
    double half_fov_degrees = 20.0;      // the scene's fov / 2
    double coverage_margin = 1.2;        // sheet half-size / visible half-size at its distance
    double wave_amplitude = 0.05;        // < spacing / 2: neighbouring layers never touch
    double waves_per_sheet = 2.5;        // wavelengths across a sheet, the same apparent size for every layer
    bool farthest_first = false;         // true: the z-buffer's worst case, where hierarchical Z culls nothing
};

Mesh make_occlusion(const OcclusionParams& params) {
    Mesh mesh;
    const int n = params.cells_per_side;
    for (int step = 0; step < params.layers; ++step) {
        const int layer = params.farthest_first ? params.layers - 1 - step : step;
        const double distance = params.first_distance + layer * params.spacing;
        const double half_size =
            params.coverage_margin * distance * std::tan(params.half_fov_degrees * kPi / 180.0);
        const double k = 2.0 * kPi * params.waves_per_sheet / (2.0 * half_size);  // wave number
        const double phase_x = 0.7 * layer, phase_y = 1.3 * layer;                 // layers differ
        const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const double x = half_size * (2.0 * i / n - 1.0), y = half_size * (2.0 * j / n - 1.0);
                const double sx = std::sin(k * x + phase_x), cx = std::cos(k * x + phase_x);
                const double sy = std::sin(k * y + phase_y), cy = std::cos(k * y + phase_y);
                const double height = params.wave_amplitude * sx * cy;  // towards the camera (+z)
                const double dh_dx = params.wave_amplitude * k * cx * cy, dh_dy = -params.wave_amplitude * k * sx * sy;
                mesh.add_vertex({x, y, -distance + height}, normalized({-dh_dx, -dh_dy, 1.0}));
            }
        // x right, y up, seen from +z: (i, j) -> (i + 1, j) -> (i + 1, j + 1) is counter-clockwise.
        auto at = [&](int i, int j) { return first + static_cast<uint32_t>(j * (n + 1) + i); };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                mesh.triangles.insert(mesh.triangles.end(), {{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
                                                             {at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
    }
    return mesh;
}

// ------------------------------------------------------------------------------------------------ output

void append_le32(std::string& out, uint32_t value) {
    for (int byte = 0; byte < 4; ++byte) out.push_back(static_cast<char>((value >> (8 * byte)) & 0xff));
}
void append_float(std::string& out, double value) {
    const float f = static_cast<float>(value);
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    append_le32(out, bits);
}

// Binary little-endian PLY: x y z nx ny nz as float, faces as a uchar count and uint indices.
std::string ply_bytes(const Mesh& mesh, const std::string& comment) {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment " + comment +
                      "\ncomment made by tools/make_bench_meshes\nelement vertex " +
                      std::to_string(mesh.positions.size()) +
                      "\nproperty float x\nproperty float y\nproperty float z\n"
                      "property float nx\nproperty float ny\nproperty float nz\nelement face " +
                      std::to_string(mesh.triangles.size()) +
                      "\nproperty list uchar uint vertex_indices\nend_header\n";
    out.reserve(out.size() + mesh.positions.size() * 24 + mesh.triangles.size() * 13);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3 p = mesh.positions[i], n = mesh.normals[i];
        for (double v : {p.x, p.y, p.z, n.x, n.y, n.z}) append_float(out, v);
    }
    for (const Triangle& t : mesh.triangles) {
        out.push_back(3);
        for (uint32_t index : t) append_le32(out, index);
    }
    return out;
}

// Writes `bytes` to `path` through `path`.tmp and a rename; false (with a message) on failure.
bool write_atomically(const std::filesystem::path& path, const std::string& bytes) {
    const std::filesystem::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            std::cerr << "make_bench_meshes: " << temporary.string() << ": cannot write\n";
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            return false;
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::cerr << "make_bench_meshes: cannot rename " << temporary.string() << " to " << path.string() << ": "
                  << error.message() << "\n";
        std::filesystem::remove(temporary, error);
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 || std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help") {
        std::cerr << "usage: make_bench_meshes OUT_DIR   (writes icosphere.ply, organic.ply, occlusion.ply)\n";
        return argc == 2 ? kExitOk : kExitUsage;
    }
    const std::filesystem::path out_dir = argv[1];
    std::error_code error;
    std::filesystem::create_directories(out_dir, error);
    if (error) {
        std::cerr << "make_bench_meshes: cannot create " << out_dir.string() << ": " << error.message() << "\n";
        return kExitWriteError;
    }

    auto away_from_origin = [](Vec3 centroid) { return centroid; };
    auto towards_camera = [](Vec3) { return Vec3{0, 0, 1}; };

    struct Output {
        const char* file;
        Mesh mesh;
        std::string comment;
        bool valid;
    };
    std::vector<Output> outputs;
    {
        Mesh icosphere = make_icosphere(6);
        const bool valid = check_mesh("icosphere", icosphere, away_from_origin);
        outputs.push_back({"icosphere.ply", std::move(icosphere),
                           "icosahedron subdivided 6 times, unit radius, normals = positions", valid});
    }
    {
        Mesh organic = make_organic(OrganicParams{});
        const bool valid = check_mesh("organic", organic, away_from_origin);
        outputs.push_back({"organic.ply", std::move(organic),
                           "noise-displaced jittered cube sphere, area-weighted vertex normals", valid});
    }
    {
        const OcclusionParams params;
        Mesh occlusion = make_occlusion(params);
        const bool valid = check_mesh("occlusion", occlusion, towards_camera);
        outputs.push_back({"occlusion.ply", std::move(occlusion),
                           std::to_string(params.layers) + " wavy sheets facing +z, farthest first", valid});
    }

    int status = kExitOk;
    for (const Output& output : outputs) {
        if (!output.valid) {
            std::cerr << "make_bench_meshes: " << output.file << " fails its checks; not written\n";
            status = kExitWriteError;
            continue;
        }
        if (!write_atomically(out_dir / output.file, ply_bytes(output.mesh, output.comment))) status = kExitWriteError;
    }
    return status;
}
