#include "io/text_scanner.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace hmfnet {

TextScanner::TextScanner(std::string path) : m_path(std::move(path)) {
  std::ifstream in(m_path, std::ios::binary);
  if (!in) throw InputError(m_path, 0, "cannot open file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(m_path, 0, "read error");
  m_text = std::move(buffer).str();
}

TextScanner::TextScanner(std::string path, std::int64_t begin, std::int64_t end)
    : m_path(std::move(path)), m_begin(begin) {
  const std::int64_t size = file_size(m_path);
  end = std::min(end, size);
  m_truncated = end < size;
  if (begin < 0 || begin > end) return;
  std::ifstream in(m_path, std::ios::binary);
  if (!in) throw InputError(m_path, 0, "cannot open file for reading");
  m_text.resize(static_cast<std::size_t>(end - begin));
  in.seekg(begin);
  in.read(m_text.data(), static_cast<std::streamsize>(m_text.size()));
  if (!in) throw InputError(m_path, 0, "read error at byte " + std::to_string(begin));
  // A prefix keeps whole lines only (a range cut at line starts already ends with one).
  if (m_truncated) m_text.resize(m_text.rfind('\n') + 1);
}

std::int64_t TextScanner::file_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path, 0, "cannot open file for reading");
  const auto size = static_cast<std::int64_t>(in.tellg());
  if (size < 0) throw InputError(path, 0, "not a regular file (its size is unknown)");
  return size;
}

std::int64_t TextScanner::line_start_at_or_after(const std::string& path, std::int64_t offset) {
  if (offset <= 0) return 0;
  const std::int64_t size = file_size(path);
  if (offset >= size) return size;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open file for reading");
  // The byte before `offset` says whether a line starts there; otherwise the next '\n' does.
  in.seekg(offset - 1);
  std::int64_t at = offset - 1;
  for (char c = 0; in.get(c); ++at) {
    if (c == '\n') return at + 1;
  }
  return at;
}

std::int64_t TextScanner::count_lines() const {
  const auto newlines = std::count(m_text.begin(), m_text.end(), '\n');
  return newlines + (!m_text.empty() && m_text.back() != '\n' ? 1 : 0);
}

void TextScanner::rewind(std::int64_t offset, std::int64_t line) {
  m_pos = static_cast<std::size_t>(offset - m_begin);
  m_line = line;
}

bool TextScanner::next_line(std::string_view& line) {
  if (m_pos >= m_text.size()) return false;
  const std::size_t end = m_text.find('\n', m_pos);
  const std::size_t stop = end == std::string::npos ? m_text.size() : end;
  line = std::string_view(m_text).substr(m_pos, stop - m_pos);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  m_pos = stop + 1;
  ++m_line;
  return true;
}

void TextScanner::split(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
}

std::int64_t TextScanner::parse_integer(std::string_view token, const char* what) const {
  std::int64_t value = 0;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (!token.empty() && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) {
    fail(std::string(what) + " '" + std::string(token) + "' is out of the integer range");
  }
  if (ec != std::errc() || ptr != last || first == last) {
    fail(std::string(what) + " '" + std::string(token) + "' is not an integer");
  }
  return value;
}

double TextScanner::parse_real(std::string_view token, const char* what) const {
  double value = 0.0;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (!token.empty() && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) {
    fail(std::string(what) + " '" + std::string(token) + "' is out of the double range");
  }
  if (ec != std::errc() || ptr != last || first == last) {
    fail(std::string(what) + " '" + std::string(token) + "' is not a number");
  }
  return value;
}

void TextScanner::fail(const std::string& cause) const { throw InputError(m_path, m_line, cause); }

}  // namespace hmfnet
