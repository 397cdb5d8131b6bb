#pragma once
// Line-by-line reading of a text file loaded whole into memory, with token parsing that reports
// errors as "FILE:LINE: cause". std::from_chars: locale-independent, no exceptions, whole-token.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hmfnet {

class TextScanner {
 public:
  /// Reads the whole file; throws InputError if it cannot be opened or read.
  explicit TextScanner(std::string path);

  /// Next line (without the newline) into `line`; false at end of file.
  bool next_line(std::string_view& line);
  /// 1-based number of the line last returned.
  std::int64_t line_number() const { return m_line; }
  const std::string& path() const { return m_path; }

  /// Splits on blanks (space, tab, CR).
  static void split(std::string_view line, std::vector<std::string_view>& tokens);

  std::int64_t parse_integer(std::string_view token, const char* what) const;
  double parse_real(std::string_view token, const char* what) const;
  [[noreturn]] void fail(const std::string& cause) const;

 private:
  std::string m_path;
  std::string m_text;
  std::size_t m_pos = 0;
  std::int64_t m_line = 0;
};

}  // namespace hmfnet
