#pragma once
// The provenance record stored with every output: what made it, with which parameters and seed,
// from which code version and command line (the CLI's as typed, or what an embedding such as the
// Python module says it is).
#include <nlohmann/json.hpp>
#include <string>

namespace hmfnet::app {

/// {"producer": ..., "parameters": {...}, "hmfnet_version", "git_commit", "command_line"}.
std::string provenance(const std::string& producer, const nlohmann::json& parameters);

/// The command line the provenance records.
const std::string& command_line();
void set_command_line(int argc, char** argv);
void set_command_line(const std::string& text);

}  // namespace hmfnet::app
