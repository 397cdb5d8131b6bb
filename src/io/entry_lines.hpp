#pragma once
// The entry lines the text writers share (Matrix Market coordinate data, edge lists).
#include <ostream>

#include "network/network.hpp"

namespace hmfnet {

enum class Triangle { lower, upper };

/// One line "i j" (and " w" for a weighted network, 17 significant digits, so the double round-
/// trips) per stored entry of one triangle of the symmetric matrix (the diagonal included),
/// indices offset by `base` (1 for Matrix Market, 0 for edge lists), in row order.
void write_entry_lines(std::ostream& out, const Network& network, Triangle triangle, int base);

}  // namespace hmfnet
