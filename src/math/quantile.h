// Quantiles of a sample (host only): medians of neighbour heights, error percentiles.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace urbis {

/// The q-quantile, q in [0, 1], of a non-empty sample by linear interpolation between the
/// closest ranks (NumPy's default, Hyndman & Fan type 7): q = 0.5 is the median, and the
/// mean of the two middle values for an even count. Sorts `values`.
template <typename T>
double quantile(std::vector<T>& values, double q) {
    std::sort(values.begin(), values.end());
    const double rank = q * double(values.size() - 1);
    const size_t below = size_t(std::floor(rank));
    const size_t above = std::min(below + 1, values.size() - 1);
    return double(values[below]) + (rank - double(below)) * (double(values[above]) - double(values[below]));
}

} // namespace urbis
