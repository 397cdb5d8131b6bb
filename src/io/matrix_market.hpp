#pragma once
// Matrix Market coordinate format (NIST, Boisvert, Pozo & Remington 1996) for adjacency matrices.
// Read: `%%MatrixMarket matrix coordinate (pattern|integer|real) (symmetric|general)`, 1-based
// indices, square. A `general` matrix must be symmetric, or is symmetrised as (A+A^T)/2 with a
// warning when ReadOptions::asymmetry says so.
// Write: `symmetric`, lower triangle, `pattern` for 0/1 networks and `real` (17 significant
// digits, exact round trip) otherwise; the file appears only when complete.
#include <string>

#include "io/read_options.hpp"

namespace hmfnet {

ReadResult read_matrix_market(const std::string& path, const ReadOptions& options = {});

/// `comment` lines are written as `%` lines after the header (provenance).
void write_matrix_market(const std::string& path, const Network& network,
                         const std::string& comment = {});

}  // namespace hmfnet
