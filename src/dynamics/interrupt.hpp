#pragma once
// SIGINT / SIGTERM during a long run: the handler only sets a flag (async-signal-safe); the
// simulation polls it at every time-series record (collectively over ranks), writes a final
// checkpoint if the run has one, and returns with SimulationResult::interrupted set. A second
// signal of the same kind ends the process at once (the handler restores the default action).
#include <stdexcept>
#include <string>

namespace hmfnet {

/// Installs the handlers for SIGINT and SIGTERM (idempotent). Called by the CLI and, around an
/// integration only, by the Python module (src/python/python_commands.cpp, which restores the
/// interpreter's handler after), not by the library: an embedding keeps its own signal policy.
void install_interrupt_handlers();

/// The signal that asked for a stop (SIGINT, SIGTERM), or 0.
int interrupt_signal();

/// Sets the flag as the handler would (tests) or clears it (0).
void set_interrupt_signal(int signal);

/// Thrown by the CLI when a run stopped on a signal: main() prints it and exits 128 + signal.
class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted(int signal, const std::string& what)
      : std::runtime_error(what), m_signal(signal) {}
  int signal() const { return m_signal; }

 private:
  int m_signal;
};

}  // namespace hmfnet
