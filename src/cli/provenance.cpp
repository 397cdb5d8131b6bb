#include "cli/provenance.hpp"

#include "cli/commands.hpp"
#include "hmfnet/version.hpp"

namespace hmfnet::cli {

std::string provenance(const std::string& producer, const nlohmann::json& parameters) {
  nlohmann::json j;
  j["producer"] = producer;
  j["parameters"] = parameters;
  j["hmfnet_version"] = k_version;
  j["git_commit"] = k_git_commit;
  j["command_line"] = command_line();
  return j.dump();
}

}  // namespace hmfnet::cli
