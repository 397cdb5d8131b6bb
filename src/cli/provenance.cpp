#include "cli/provenance.hpp"

#include "cli/commands.hpp"
#include "core/version.hpp"

namespace hmfnet::cli {

std::string provenance(const std::string& producer, const nlohmann::json& parameters) {
  nlohmann::json j;
  j["producer"] = producer;
  j["parameters"] = parameters;
  j["hmfnet_version"] = version();
  j["git_commit"] = git_commit();
  j["command_line"] = command_line();
  return j.dump();
}

}  // namespace hmfnet::cli
