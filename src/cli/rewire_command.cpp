// `hmfnet rewire`: the command line's face of the rewiring (app/network_rewiring.hpp).
#include <iostream>

#include "app/network_rewiring.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/read_flags.hpp"

namespace hmfnet::cli {

namespace {

void run(const RewireFlags& f) {
  app::check_rewire(f.request);
  const RewiringResult r = app::rewire(f.request, f.read.read(f.request.input));
  if (!is_root()) return;
  std::cerr << "wrote " << f.request.output << ": rho " << r.initial_rho << " -> " << r.final_rho
            << " (" << r.swaps << " swaps in " << r.attempts << " attempts; degrees unchanged)\n";
}

}  // namespace

void add_rewire_command(CLI::App& app) {
  static RewireFlags f;
  add_rewire_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli
