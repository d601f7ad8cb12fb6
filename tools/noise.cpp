// Perlin's improved gradient noise: the permutation from a fixed seed, one octave, and the fractal sum.
#include "tools/noise.h"

#include <cmath>
#include <cstddef>
#include <numeric>
#include <utility>

namespace raster::tools {

GradientNoise::GradientNoise(uint64_t seed) {
    std::array<uint8_t, 256> permutation;
    std::iota(permutation.begin(), permutation.end(), uint8_t{0});
    SplitMix64 random(seed);
    for (size_t i = permutation.size() - 1; i > 0; --i) std::swap(permutation[i], permutation[random.next() % (i + 1)]);
    for (size_t i = 0; i < 512; ++i) table_[i] = permutation[i & 255];
}

double GradientNoise::operator()(Vec3 p) const {
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

double GradientNoise::fractal(Vec3 p, int octaves) const {
    double sum = 0, amplitude = 1;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * (*this)(p);
        p = 2.0 * p;
        amplitude *= 0.5;
    }
    return sum;
}

}  // namespace raster::tools
