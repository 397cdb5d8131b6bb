#pragma once
// Whitespace edge lists: one undirected edge `u v` or `u v w` per line, `#` starts a comment
// (whole line or trailing), blank lines ignored. Node indices are 0- or 1-based
// (ReadOptions::edge_list_base). Each unordered pair may appear once: `u v` and later `v u` is a
// duplicate. Either every line has a weight or none does. A first line `# nodes N` (written by
// write_edge_list) gives the node count, so isolated trailing nodes survive a round trip;
// ReadOptions::edge_list_nodes overrides it.
#include <string>

#include "io/read_options.hpp"

namespace hmfnet {

ReadResult read_edge_list(const std::string& path, const ReadOptions& options = {});

/// Writes `u v [w]` lines (u <= v, 0-based, `# ` comment first); the file appears when complete.
void write_edge_list(const std::string& path, const Network& network,
                     const std::string& comment = {});

}  // namespace hmfnet
