// The reductions of ParallelSession (parallel/parallel_session.hpp): every rank receives the
// same element-wise result, whichever rank holds each extreme, so a rule fed by them (the
// thread trial's inputs) decides alike on every rank. Run at 1 and 2 ranks (label mpi). And a
// process started without a launcher runs as a singleton that starts no daemon.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <vector>

#include "parallel/parallel_session.hpp"

using namespace hmfnet;

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

TEST_CASE("A process no launcher started is an isolated Open MPI singleton", "[parallel_session]") {
  // mpirun (the mpi label) gives each rank OMPI_COMM_WORLD_SIZE: a launched rank is left alone.
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) {
    CHECK(ParallelSession::ranks() >= 1);
    return;
  }
  // The session set both before MPI_Init (or the user did, whose value it keeps): without them
  // every command paid 0.3 s for a daemon and a probe of every messaging layer.
  CHECK(ParallelSession::ranks() == 1);
  CHECK(std::getenv("OMPI_MCA_ess_singleton_isolated") != nullptr);
  CHECK(std::getenv("OMPI_MCA_pml") != nullptr);
}
