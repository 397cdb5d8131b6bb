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
  /// Reads only the bytes [begin, end) of the file (clamped to its size), then drops a last
  /// line cut short by `end`: one rank's share of a file parsed in parallel, or a prefix. Line
  /// numbers count from the range's start until set_lines_before says how many lines precede it.
  TextScanner(std::string path, std::int64_t begin, std::int64_t end);

  /// Size of a file in bytes; throws InputError if it cannot be opened.
  static std::int64_t file_size(const std::string& path);
  /// Offset of the first line that starts at or after `offset` (a line starts at 0 or after a
  /// '\n'); the file size if none does. What cuts a file into byte ranges of whole lines.
  static std::int64_t line_start_at_or_after(const std::string& path, std::int64_t offset);

  /// Next line (without the newline) into `line`; false at end of file.
  bool next_line(std::string_view& line);
  /// 1-based number of the line last returned.
  std::int64_t line_number() const { return m_line; }
  const std::string& path() const { return m_path; }
  /// File offset of the next byte next_line would read.
  std::int64_t offset() const { return m_begin + static_cast<std::int64_t>(m_pos); }
  /// True when the text read stops before the end of the file (a range, or a prefix).
  bool truncated() const { return m_truncated; }
  /// Lines in the text read (a last line without '\n' counts).
  std::int64_t count_lines() const;
  /// Numbers the lines read so far and later as if `lines` lines preceded the text read.
  void set_lines_before(std::int64_t lines) {
    m_line += lines - m_lines_before, m_lines_before = lines;
  }
  /// Goes back to a point saved from offset() and line_number() (to read a line again).
  void rewind(std::int64_t offset, std::int64_t line);

  /// Splits on blanks (space, tab, CR).
  static void split(std::string_view line, std::vector<std::string_view>& tokens);

  std::int64_t parse_integer(std::string_view token, const char* what) const;
  double parse_real(std::string_view token, const char* what) const;
  [[noreturn]] void fail(const std::string& cause) const;

 private:
  std::string m_path;
  std::string m_text;
  std::int64_t m_begin = 0;  ///< file offset of m_text[0]
  bool m_truncated = false;
  std::size_t m_pos = 0;
  std::int64_t m_line = 0;
  std::int64_t m_lines_before = 0;
};

}  // namespace hmfnet
