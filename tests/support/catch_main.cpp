// Catch2 runner for the tests that need no MPI.
#include "support/catch_session.hpp"

int main(int argc, char** argv) { return hmfnet::test::run_catch_session(argc, argv); }
