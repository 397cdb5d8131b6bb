#include "cli/read_flags.hpp"

#include <iostream>

#include "cli/commands.hpp"
#include "cli/validators.hpp"
#include "io/network_file.hpp"

namespace hmfnet::cli {

void ReadFlags::add_to(CLI::App* command) {
  command->add_flag("--symmetrize", symmetrize,
                    "Matrix Market 'general' input that is not symmetric: use (A+A^T)/2 "
                    "(with a warning) instead of rejecting it");
  command->add_option("--index-base", index_base, "Edge lists: first node index (0 or 1)")
      ->check(CLI::IsMember({0, 1}));
  command->add_option("--nodes", nodes, "Edge lists: number of nodes (default: largest index+1)")
      ->check(k_non_negative);
}

Network ReadFlags::read(const std::string& path) const {
  ReadOptions options;
  options.asymmetry = symmetrize ? AsymmetryPolicy::symmetrize : AsymmetryPolicy::reject;
  options.edge_list_base = index_base;
  options.edge_list_nodes = nodes;
  ReadResult r = read_network(path, options);
  if (is_root()) {
    for (const auto& w : r.warnings) std::cerr << w << '\n';
  }
  return std::move(r.network);
}

}  // namespace hmfnet::cli
