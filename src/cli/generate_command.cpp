// `hmfnet generate er|sf|sbm|complete|regular`: the command line's face of the generators
// (app/network_generation.hpp): options to a request, the file written, a line on stderr saying
// what it holds and what it took.
#include <cmath>
#include <iostream>

#include "app/network_generation.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"

namespace hmfnet::cli {

namespace {

void report(const app::GeneratedFile& f) {
  if (!is_root()) return;
  if (f.implicit) {
    std::cerr << "wrote " << f.path << ": the complete graph, N = " << f.n
              << ", edges = " << f.edges << " (stored implicitly)\n";
    return;
  }
  std::cerr << "wrote " << f.path << ": N = " << f.n << ", edges = " << f.edges
            << ", mean degree = " << static_cast<double>(f.nnz) / f.n << " (" << f.seconds
            << " s on " << f.ranks << " rank(s); peak memory per rank, MB:";
  for (const double mb : f.peak_rss_mb_per_rank) std::cerr << ' ' << std::lround(mb);
  std::cerr << ")\n";
}

template <class Request>
void run(const Request& r) {
  report(app::generate_file(r));
}

}  // namespace

void add_generate_command(CLI::App& app) {
  static GenerateFlags flags;
  add_generate_options(app, flags,
                       {[] { run(flags.er); }, [] { run(flags.sf); }, [] { run(flags.sbm); },
                        [] { run(flags.complete); }, [] { run(flags.regular); }});
}

}  // namespace hmfnet::cli
