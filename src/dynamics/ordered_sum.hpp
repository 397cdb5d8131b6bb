#pragma once
// Sums over rows whose result does not depend on the number of OpenMP threads: rows are cut into
// fixed blocks, each block summed in order (in parallel across blocks), then the block sums in
// order. 1 and 2 threads therefore give bit-identical observables.
#include <cstddef>
#include <vector>

namespace hmfnet {

/// out[b] = sum over rows r of values[r * width + b], for b < width.
void ordered_column_sums(const std::vector<double>& values, std::size_t rows, int width,
                         std::vector<double>& out);

}  // namespace hmfnet
