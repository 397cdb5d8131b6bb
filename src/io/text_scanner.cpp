#include "io/text_scanner.hpp"

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
