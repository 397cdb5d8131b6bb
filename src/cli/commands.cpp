// What every command shares: which rank reports.
#include "cli/commands.hpp"

#include "parallel/parallel_session.hpp"

namespace hmfnet::cli {

bool is_root() { return ParallelSession::rank() == 0; }

}  // namespace hmfnet::cli
