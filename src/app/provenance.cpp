#include "app/provenance.hpp"

#include "core/version.hpp"

namespace hmfnet::app {

namespace {
std::string g_command_line;
}

std::string provenance(const std::string& producer, const nlohmann::json& parameters) {
  nlohmann::json j;
  j["producer"] = producer;
  j["parameters"] = parameters;
  j["hmfnet_version"] = version();
  j["git_commit"] = git_commit();
  j["command_line"] = command_line();
  return j.dump();
}

const std::string& command_line() { return g_command_line; }

void set_command_line(int argc, char** argv) {
  g_command_line.clear();
  for (int k = 0; k < argc; ++k) {
    if (k > 0) g_command_line += ' ';
    g_command_line += argv[k];
  }
}

void set_command_line(const std::string& text) { g_command_line = text; }

}  // namespace hmfnet::app
