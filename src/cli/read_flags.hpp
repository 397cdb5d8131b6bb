#pragma once
// Options every command that reads a network file shares, and the read itself (warnings go to
// stderr on the root rank).
#include <CLI/CLI.hpp>
#include <string>

#include "io/read_options.hpp"

namespace hmfnet::cli {

struct ReadFlags {
  bool symmetrize = false;
  int index_base = 0;
  int nodes = 0;

  void add_to(CLI::App* command);
  Network read(const std::string& path) const;
};

}  // namespace hmfnet::cli
