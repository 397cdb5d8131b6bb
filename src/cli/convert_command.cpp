// `hmfnet convert IN -o OUT.h5`: the command line's face of the conversion
// (app/network_conversion.hpp): the output checked before the input is read, the file written,
// what the renumbering did and what it took on stderr.
#include <cmath>
#include <iostream>

#include "app/network_conversion.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/read_flags.hpp"

namespace hmfnet::cli {

namespace {

void run(const ConvertFlags& f) {
  app::check_convert(f.request);
  const app::ConvertedFile file =
      app::convert(f.request, f.read.read_distributed_rows(f.request.input));
  if (!is_root()) return;
  for (const std::string& note : file.notes) std::cerr << note << '\n';
  std::cerr << "wrote " << f.request.output << ": N = " << file.n
            << ", stored entries = " << file.nnz << " (" << file.seconds << " s on " << file.ranks
            << " rank(s); peak memory per rank, MB:";
  for (const double mb : file.peak_rss_mb_per_rank) std::cerr << ' ' << std::lround(mb);
  std::cerr << ")\n";
}

}  // namespace

void add_convert_command(CLI::App& app) {
  static ConvertFlags f;
  add_convert_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli
