// Entrywise magnitudes of glm matrices for the precision model: |M|, its largest entry and its largest row sum.
#pragma once

#include <algorithm>
#include <cmath>

namespace raster::oracle {

// |m|, entry by entry.
template <typename Matrix>
Matrix absolute(const Matrix& m) {
    Matrix a;
    for (int c = 0; c < m.length(); ++c)
        for (int r = 0; r < m.length(); ++r) a[c][r] = std::fabs(m[c][r]);
    return a;
}

template <typename Matrix>
double largest_entry(const Matrix& m) {
    double largest = 0.0;
    for (int c = 0; c < m.length(); ++c)
        for (int r = 0; r < m.length(); ++r) largest = std::max(largest, m[c][r]);
    return largest;
}

// ||m||_inf of a non-negative matrix: its largest row sum.
template <typename Matrix>
double largest_row_sum(const Matrix& m) {
    double largest = 0.0;
    for (int r = 0; r < m.length(); ++r) {
        double sum = 0.0;
        for (int c = 0; c < m.length(); ++c) sum += m[c][r];
        largest = std::max(largest, sum);
    }
    return largest;
}

}  // namespace raster::oracle
