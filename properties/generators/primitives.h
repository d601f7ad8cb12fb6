// The draws every generator is built from, for the generator sources: each is called inside an rc::gen::exec and
// draws uniformly (not scaled by RapidCheck's size), so every case is a full draw.
#pragma once

#include <vector>

#include <glm/vec3.hpp>
#include <rapidcheck.h>

namespace raster::properties {

// The generator sources write RapidCheck's combinators as gen::... and its generator type as Gen<T>.
namespace gen = rc::gen;
using rc::Gen;

constexpr double kPi = 3.14159265358979323846;

// Uniform in [lo, hi], inclusive, at full size whatever RapidCheck's current size; shrinks towards lo.
template <class T>
Gen<T> uniform(T lo, T hi) {
    return gen::resize(100, gen::inRange<T>(lo, static_cast<T>(hi + 1)));
}

// Uniform in [0, 1) on a grid of 2^-24.
double unit();

// Log-uniform in [lo, hi] (lo > 0).
double log_uniform(double lo, double hi);

// True or false, evenly.
bool coin();

// Uniform in [-1, 1) on a grid of 2^-23.
double signed_unit();

// Each coordinate uniform in [-scale, scale).
glm::vec3 random_vector(double scale);

// Uniform on the unit sphere.
glm::vec3 random_direction();

// A random permutation of 0 .. n-1.
Gen<std::vector<int>> permutations(int n);

}  // namespace raster::properties
