// The reductions of ParallelSession (parallel/parallel_session.hpp): every rank receives the
// same element-wise result, whichever rank holds each extreme, so a rule fed by them (the
// thread trial's inputs) decides alike on every rank. Run at 1 and 2 ranks (label mpi). And a
// process started without a launcher runs as a singleton that starts no daemon.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "parallel/parallel_session.hpp"

using namespace hmfnet;

TEST_CASE("The ranks of one machine number themselves in rank order", "[parallel_session]") {
  // mpirun starts the test's ranks on this one machine: each is its rank among them all.
  const ParallelSession::MachineRanks m = ParallelSession::machine_ranks();
  CHECK(m.count == ParallelSession::ranks());
  CHECK(m.index == ParallelSession::rank());
}

TEST_CASE("Element-wise max and sum over ranks reach every rank", "[parallel_session]") {
  const auto r = static_cast<double>(ParallelSession::rank());
  const auto p = static_cast<double>(ParallelSession::ranks());
  // The max of x, of -x (a min) and of a value only the last rank raises.
  std::vector<double> most{r, -r, r == p - 1 ? 5.0 : 1.0};
  ParallelSession::max_in_place(most);
  CHECK(most == std::vector<double>{p - 1, 0.0, 5.0});
  std::vector<double> total{1.0, r};
  ParallelSession::sum_in_place(total);
  CHECK(total == std::vector<double>{p, p * (p - 1) / 2});
  std::vector<double> none;
  ParallelSession::max_in_place(none);
  CHECK(none.empty());
}

namespace {

// The process ids of this process's children, from every thread's /proc/self/task/*/children
// (Linux); nullopt where the kernel does not list them.
std::optional<std::vector<std::string>> child_processes() {
  std::vector<std::string> children;
  bool listed = false;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream file(task.path() / "children");
    if (!file) continue;
    listed = true;
    for (std::string id; file >> id;) children.push_back(id);
  }
  if (!listed) return std::nullopt;
  return children;
}

}  // namespace

TEST_CASE("A process no launcher started is an isolated Open MPI singleton", "[parallel_session]") {
  if (ParallelSession::started_by_launcher()) {  // the mpi label's runs: left alone
    CHECK(ParallelSession::ranks() >= 1);
    return;
  }
  CHECK(ParallelSession::ranks() == 1);
  // No daemon: Open MPI 4 forks one for a singleton that is not isolated (measured: one child).
  const auto children = child_processes();
  if (children) {
    CHECK(children->empty());
  } else {
    WARN("this kernel lists no child processes (/proc/self/task/*/children): not checked");
  }
  // Nothing of the singleton's start is left for the processes this one starts: an mpirun
  // started with OMPI_MCA_ess=singleton or OMPI_MCA_pmix=isolated in its environment fails.
  CHECK(std::getenv("OMPI_MCA_ess") == nullptr);
  CHECK(std::getenv("OMPI_MCA_pmix") == nullptr);
}
