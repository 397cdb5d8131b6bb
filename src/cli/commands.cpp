// What every command shares: the command line as typed (provenance) and which rank reports.
#include "cli/commands.hpp"

#include "parallel/parallel_session.hpp"

namespace hmfnet::cli {

namespace {
std::string g_command_line;
}

const std::string& command_line() { return g_command_line; }

void set_command_line(int argc, char** argv) {
  g_command_line.clear();
  for (int k = 0; k < argc; ++k) {
    if (k > 0) g_command_line += ' ';
    g_command_line += argv[k];
  }
}

void set_command_line(const std::string& text) { g_command_line = text; }

bool is_root() { return ParallelSession::rank() == 0; }

}  // namespace hmfnet::cli
