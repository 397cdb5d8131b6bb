#include "cli/read_flags.hpp"

#include <iostream>

#include "cli/commands.hpp"
#include "io/network_file.hpp"

namespace hmfnet::cli {

namespace {
void print_warnings(const std::vector<std::string>& warnings) {
  if (!is_root()) return;
  for (const auto& w : warnings) std::cerr << w << '\n';
}
}  // namespace

// ReadFlags::add_to is part of the grammar: cli/command_options.cpp.

Network ReadFlags::read(const std::string& path) const {
  ReadResult r = read_network(path, app::read_options(*this));
  print_warnings(r.warnings);
  return std::move(r.network);
}

NetworkInput ReadFlags::read_input(const std::string& path) const {
  NetworkInput r = read_network_input(path, app::read_options(*this));
  print_warnings(r.warnings);
  return r;
}

DistributedInput ReadFlags::read_distributed(const std::string& path) const {
  DistributedInput r = read_distributed_input(path, app::read_options(*this));
  print_warnings(r.warnings);
  return r;
}

DistributedRows ReadFlags::read_distributed_rows(const std::string& path) const {
  DistributedRows r = hmfnet::read_distributed_rows(path, app::read_options(*this));
  print_warnings(r.warnings);
  return r;
}

}  // namespace hmfnet::cli
