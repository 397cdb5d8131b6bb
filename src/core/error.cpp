#include "core/error.hpp"

#include <cstdio>

namespace hmfnet {

namespace {
std::string place(const std::string& file, std::int64_t line) {
  return line > 0 ? file + ":" + std::to_string(line) : file;
}
}  // namespace

InputError::InputError(const std::string& file, std::int64_t line, const std::string& cause)
    : std::runtime_error(place(file, line) + ": " + cause),
      m_file(file),
      m_line(line),
      m_cause(cause) {}

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

ParameterError::ParameterError(const std::string& name, const std::string& cause,
                               const std::string& allowed)
    : std::invalid_argument(name + ": " + cause + " (allowed: " + allowed + ")") {}

}  // namespace hmfnet
