#pragma once
// The provenance record stored with every output: what made it, with which parameters and seed,
// from which code version and command line.
#include <nlohmann/json.hpp>
#include <string>

namespace hmfnet::cli {

/// {"producer": ..., "parameters": {...}, "hmfnet_version", "git_commit", "command_line"}.
std::string provenance(const std::string& producer, const nlohmann::json& parameters);

}  // namespace hmfnet::cli
