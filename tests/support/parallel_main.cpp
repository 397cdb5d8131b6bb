// Catch2 runner for tests that touch Tpetra/Anasazi: the ParallelSession (MPI + Kokkos) must
// outlive every distributed object, so it is created here, around the whole session.
#include "parallel/parallel_session.hpp"
#include "support/catch_session.hpp"

int main(int argc, char** argv) {
  hmfnet::ParallelSession session(&argc, &argv);
  return hmfnet::test::run_catch_session(argc, argv);
}
