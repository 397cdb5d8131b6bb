#pragma once
// Runs Catch2's session: every test binary's main() ends here, so that Catch2 2.x's
// implementation (one header) is compiled once, in support/catch_session.cpp, not in each main.

namespace hmfnet::test {

/// Catch::Session().run(argc, argv): the command line's test selection, reporters and exit code.
int run_catch_session(int argc, char** argv);

}  // namespace hmfnet::test
