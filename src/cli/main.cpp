// hmfnet: command-line entry point. `hmfnet --help` lists the subcommands.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "app/provenance.hpp"
#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "dynamics/interrupt.hpp"
#include "parallel/parallel_session.hpp"

namespace {

int run(int argc, char** argv) {
  CLI::App app{"hmfnet: the Hamiltonian Mean Field model of coupled rotors on networks"};
  hmfnet::cli::configure_app(app);
  hmfnet::cli::add_generate_command(app);
  hmfnet::cli::add_rewire_command(app);
  hmfnet::cli::add_convert_command(app);
  hmfnet::cli::add_spectrum_command(app);
  hmfnet::cli::add_theory_command(app);
  hmfnet::cli::add_simulate_command(app);
  hmfnet::cli::add_demo_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // 0: --help or --version
  } catch (const hmfnet::RunInterrupted& e) {
    std::cerr << "hmfnet: interrupted: " << e.what() << '\n';
    return 128 + e.signal();  // the shell's convention for a process ended by a signal
  } catch (const hmfnet::CollectiveError& e) {
    // Every rank holds the same message: one report, every rank exits.
    if (hmfnet::ParallelSession::rank() == 0) std::cerr << "hmfnet: error: " << e.what() << '\n';
    return 1;
  } catch (const hmfnet::ConvergenceError& e) {
    std::cerr << "hmfnet: not converged: " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "hmfnet: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // run() reports the command's own errors; this catches what escapes before it (MPI start-up,
  // allocation), which would otherwise end the process in std::terminate with no message.
  try {
    hmfnet::app::set_command_line(argc, argv);
    hmfnet::ParallelSession session(&argc, &argv);
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "hmfnet: error: " << e.what() << '\n';
    return 1;
  }
}
