// Catch2 runner for tests that touch Tpetra/Anasazi: the ParallelSession (MPI + Kokkos) must
// outlive every distributed object, so it is created here, around the whole session.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "parallel/parallel_session.hpp"

int main(int argc, char** argv) {
  hmfnet::ParallelSession session(&argc, &argv);
  return Catch::Session().run(argc, argv);
}
