// The bench meshes' randomness: a fixed-seed SplitMix64 stream and Perlin's gradient noise shuffled from it.
#pragma once

#include <array>
#include <cstdint>

#include "tools/vec3.h"

namespace raster::tools {

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
    explicit GradientNoise(uint64_t seed);

    double operator()(Vec3 p) const;

    // Fractal sum of `octaves` noises, each at twice the frequency and half the amplitude of the previous one.
    double fractal(Vec3 p, int octaves) const;

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

}  // namespace raster::tools
