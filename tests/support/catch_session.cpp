// Catch2 2.x's implementation (it is one header), compiled once for every test binary instead of
// once in each main(), and without optimisation (cmake/HmfnetTesting.cmake measured both: the
// compile time it saves, and the test time it does not cost).
#define CATCH_CONFIG_RUNNER
#include "support/catch_session.hpp"

#include <catch2/catch.hpp>

namespace hmfnet::test {

int run_catch_session(int argc, char** argv) { return Catch::Session().run(argc, argv); }

}  // namespace hmfnet::test
