// Coverage: samples placed exactly on shared edges and shared vertices are covered exactly once, and a triangle's
// covered samples equal an independent exact-integer computation on its snapped vertices.
#pragma once

#include "properties/implementation.h"

namespace raster::properties {

// Two triangles sharing an edge built to run through samples (horizontal, vertical, diagonal, any slope).
void check_shared_edge_samples_are_covered_exactly_once(const Implementation& impl);

// A fan of three to nine triangles around a vertex placed exactly on a sample.
void check_a_shared_vertex_on_a_sample_is_covered_exactly_once(const Implementation& impl);

// One triangle (random, axis-aligned, sliver, tiny, on pixel centres, off the snap grid), any sample pattern and
// snap precision, in perspective or not: its samples are exactly the reference's.
void check_covered_samples_equal_the_exact_integer_reference(const Implementation& impl);

}  // namespace raster::properties
