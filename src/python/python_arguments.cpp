#include "python/python_arguments.hpp"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <functional>
#include <utility>

namespace hmfnet::python {

namespace {

// Runs the grammar that `add` registers on `tokens` (the command line after the program name).
// Nothing is run: every subcommand's callback is a no-op here, the flags are read afterwards.
void parse(const std::function<void(CLI::App&)>& add, std::vector<std::string> tokens) {
  CLI::App app{"hmfnet (Python)"};
  cli::configure_app(app);
  add(app);
  std::reverse(tokens.begin(), tokens.end());  // CLI11 takes the arguments last first
  try {
    app.parse(std::move(tokens));
  } catch (const CLI::ParseError& e) {
    throw pybind11::value_error(e.what());
  }
}

const cli::Run k_no_work = [] {};

// The positional network argument goes last, after "--", so a name that starts with '-' is not
// read as an option.
std::vector<std::string> command_tokens(const std::string& command, const std::string& input,
                                        const std::vector<std::string>& tokens) {
  std::vector<std::string> all{command};
  all.insert(all.end(), tokens.begin(), tokens.end());
  all.emplace_back("--");
  all.push_back(input);
  return all;
}

template <class Flags>
void parse_generator(Flags cli::GenerateFlags::*member, const std::string& name, Flags& f,
                     const std::vector<std::string>& tokens) {
  cli::GenerateFlags flags;
  std::vector<std::string> all{"generate", name};
  all.insert(all.end(), tokens.begin(), tokens.end());
  all.insert(all.end(), {"--output", "python.h5"});
  parse(
      [&](CLI::App& app) {
        add_generate_options(app, flags, {k_no_work, k_no_work, k_no_work, k_no_work, k_no_work});
      },
      all);
  f = flags.*member;
}

}  // namespace

void parse_arguments(cli::SpectrumFlags& f, const std::string& input,
                     const std::vector<std::string>& tokens) {
  parse([&](CLI::App& app) { add_spectrum_options(app, f, k_no_work); },
        command_tokens("spectrum", input, tokens));
}

void parse_arguments(cli::TheoryFlags& f, const std::string& input,
                     const std::vector<std::string>& tokens) {
  parse([&](CLI::App& app) { add_theory_options(app, f, k_no_work); },
        command_tokens("theory", input, tokens));
}

void parse_generate_arguments(cli::ErFlags& f, const std::vector<std::string>& tokens) {
  parse_generator(&cli::GenerateFlags::er, "er", f, tokens);
}

void parse_generate_arguments(cli::SfFlags& f, const std::vector<std::string>& tokens) {
  parse_generator(&cli::GenerateFlags::sf, "sf", f, tokens);
}

void parse_generate_arguments(cli::SbmFlags& f, const std::vector<std::string>& tokens) {
  parse_generator(&cli::GenerateFlags::sbm, "sbm", f, tokens);
}

void parse_generate_arguments(cli::RegularFlags& f, const std::vector<std::string>& tokens) {
  parse_generator(&cli::GenerateFlags::regular, "regular", f, tokens);
}

void parse_read_arguments(cli::ReadFlags& f, const std::vector<std::string>& tokens) {
  std::vector<std::string> all{"read"};
  all.insert(all.end(), tokens.begin(), tokens.end());
  parse(
      [&](CLI::App& app) {
        CLI::App* read = app.add_subcommand("read", "read a network file");
        f.add_to(read);
      },
      all);
}

}  // namespace hmfnet::python
