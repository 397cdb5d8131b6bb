#pragma once
// Error types shared by the whole library. Every error that reaches the user names the place
// (file and line, or the parameter) and the cause in one line; the CLI prints what() and exits
// non-zero.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace hmfnet {

/// Malformed or unusable input data. what() is "FILE:LINE: cause" (line 0: "FILE: cause"),
/// the format compilers use, so editors can jump to the place.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, std::int64_t line, const std::string& cause);
  const std::string& file() const { return m_file; }
  std::int64_t line() const { return m_line; }
  const std::string& cause() const { return m_cause; }

 private:
  std::string m_file;
  std::int64_t m_line;
  std::string m_cause;
};

/// A parameter outside its allowed range: what() is "NAME: cause (allowed: RANGE)".
class ParameterError : public std::invalid_argument {
 public:
  ParameterError(const std::string& name, const std::string& cause, const std::string& allowed);
  /// A message already in the one-line form (a request's check that keeps the CLI grammar's
  /// wording, app/option_checks.hpp).
  explicit ParameterError(const std::string& message) : std::invalid_argument(message) {}
};

/// x as a message shows it: at most 6 significant digits ("0.01", "1e+300"), never the hundreds of
/// digits that std::to_string gives a large double.
std::string number_text(double x);

/// A numerical method that did not reach its tolerance: callers never get an unconverged answer
/// silently (Spectra's CompInfo convention).
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hmfnet
