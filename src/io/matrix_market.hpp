#pragma once
// Matrix Market coordinate format (NIST, Boisvert, Pozo & Remington 1996) for adjacency matrices.
// Read: `%%MatrixMarket matrix coordinate (pattern|integer|real) (symmetric|general)`, 1-based
// indices, square. A `general` matrix must be symmetric, or is symmetrised as (A+A^T)/2 with a
// warning when ReadOptions::asymmetry says so.
// Write: `symmetric`, lower triangle, `pattern` for 0/1 networks and `real` (17 significant
// digits, exact round trip) otherwise; the file appears only when complete.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/read_options.hpp"
#include "io/text_scanner.hpp"

namespace hmfnet {

ReadResult read_matrix_market(const std::string& path, const ReadOptions& options = {});

// The reader in parts, for a parallel reader (parallel/distributed_text_read.hpp) that parses
// the header on every rank and the entry lines of each rank's byte range on that rank.

enum class MatrixMarketField { pattern, integer, real };

/// What precedes the entries: the banner, comment lines and the size line.
struct MatrixMarketHeader {
  MatrixMarketField field = MatrixMarketField::pattern;
  EntrySymmetry symmetry = EntrySymmetry::symmetric;
  std::int64_t rows = 0;
  std::int64_t declared = 0;   ///< entry count on the size line
  std::int64_t size_line = 0;  ///< its line number
};

/// Parses the header from the start of `in`, leaving it at the first entry line. nullopt when
/// `in` holds only a prefix of the file that ends before the size line (read a longer one).
std::optional<MatrixMarketHeader> read_matrix_market_header(TextScanner& in);
/// What to do at an entry line once `limit` entries are held: fail naming it ("more entries
/// than declared"), or stop reading (a parallel reader, which names the line from all ranks).
enum class EntryLimit { fail, stop };
/// Appends the entries of the lines left in `in` (0-based, with their line numbers); fails
/// naming the line at the first malformed one.
void read_matrix_market_entries(TextScanner& in, const MatrixMarketHeader& header,
                                std::vector<MatrixEntry>& entries, std::int64_t limit,
                                EntryLimit at_limit = EntryLimit::fail);
/// The checks of the entry count once all are found: fewer than declared (reported at
/// `last_line`), or a size line giving more nodes than so many entries allow.
void check_matrix_market_count(const std::string& path, const MatrixMarketHeader& header,
                               std::int64_t found, std::int64_t last_line);

/// `comment` lines are written as `%` lines after the header (provenance).
void write_matrix_market(const std::string& path, const Network& network,
                         const std::string& comment = {});

}  // namespace hmfnet
