// Catch2 2.x's implementation (it is one header), compiled once for every test binary instead of
// once in each main(), and without optimisation (cmake/HmfnetTesting.cmake): the runner's own
// speed does not matter, and at -O3 this one header took 33 s of a 2-core build, three times over.
#define CATCH_CONFIG_RUNNER
#include "support/catch_session.hpp"

#include <catch2/catch.hpp>

namespace hmfnet::test {

int run_catch_session(int argc, char** argv) { return Catch::Session().run(argc, argv); }

}  // namespace hmfnet::test
