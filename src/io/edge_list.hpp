#pragma once
// Whitespace edge lists: one undirected edge `u v` or `u v w` per line, `#` starts a comment
// (whole line or trailing), blank lines ignored. Node indices are 0- or 1-based
// (ReadOptions::edge_list_base). Each unordered pair may appear once: `u v` and later `v u` is a
// duplicate. Either every line has a weight or none does. A first line `# nodes N` (written by
// write_edge_list) gives the node count, so isolated trailing nodes survive a round trip;
// ReadOptions::edge_list_nodes overrides it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/read_options.hpp"
#include "io/text_scanner.hpp"

namespace hmfnet {

ReadResult read_edge_list(const std::string& path, const ReadOptions& options = {});

// The reader in parts, for a parallel reader (parallel/distributed_text_read.hpp) that parses
// the header on every rank and the edge lines of each rank's byte range on that rank.

/// The leading comment and blank lines: "# nodes N" among them gives the node count.
struct EdgeListHeader {
  std::int64_t declared_nodes = 0;  ///< 0: none given
  std::size_t fields = 0;           ///< of the first edge line when 2 or 3 (weights or not), else 0
};

/// What the edge lines read so far say about the whole file.
struct EdgeListScan {
  std::size_t fields = 0;     ///< 2 or 3: every line must have it; 0: set by the first line
  std::int64_t largest = -1;  ///< largest node index seen, 0-based
};

/// Reads the leading comment lines of `in`, leaving it at the first edge line. nullopt when `in`
/// holds only a prefix of the file made of comments (read a longer one).
std::optional<EdgeListHeader> read_edge_list_header(TextScanner& in);
/// Appends the edges of the lines left in `in`, updating `scan`; fails naming the line at the
/// first malformed one (or one whose field count differs from scan.fields when set).
void read_edge_list_entries(TextScanner& in, const ReadOptions& options, EdgeListScan& scan,
                            std::vector<MatrixEntry>& entries);
/// The cause reported at an edge line with `found` fields after lines with `earlier`.
std::string field_count_mismatch(std::size_t found, std::size_t earlier);
/// The node count: ReadOptions::edge_list_nodes, else "# nodes N", else largest + 1, bounded by
/// io/node_count_limit.hpp for `stored` edges when the user did not give it.
NodeIndex edge_list_node_count(const std::string& path, const ReadOptions& options,
                               const EdgeListHeader& header, std::int64_t largest,
                               std::int64_t stored);

/// Writes `u v [w]` lines (u <= v, 0-based, `# ` comment first); the file appears when complete.
void write_edge_list(const std::string& path, const Network& network,
                     const std::string& comment = {});

}  // namespace hmfnet
