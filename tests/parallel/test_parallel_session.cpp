// The reductions of ParallelSession (parallel/parallel_session.hpp): every rank receives the
// same element-wise result, whichever rank holds each extreme, so a rule fed by them (the
// thread trial's inputs) decides alike on every rank. Run at 1 and 2 ranks (label mpi).
#include <catch2/catch.hpp>
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
