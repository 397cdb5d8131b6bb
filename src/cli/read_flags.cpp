#include "cli/read_flags.hpp"

#include <iostream>

#include "cli/commands.hpp"
#include "cli/validators.hpp"
#include "io/network_file.hpp"

namespace hmfnet::cli {

// ReadFlags::add_to is part of the grammar: cli/command_options.cpp.
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
