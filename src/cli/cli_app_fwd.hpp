#pragma once
// CLI11's application class, declared only: the commands pass a `CLI::App&` along to the grammar
// (command_options.cpp) and never touch its members. CLI11 is header-only, and its header took
// ~7 s to compile in each of the twelve translation units that included it (GCC 12, -O2; ~10 s
// each under clang-tidy): now only command_options.cpp and main.cpp include it.
namespace CLI {
class App;
}  // namespace CLI
