#include "cli/number_list.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/error.hpp"

namespace hmfnet::cli {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// The items of one value, empty ones kept: "1,,2" has three.
std::vector<std::string> items_of(const std::string& value) {
  std::vector<std::string> items;
  std::string::size_type start = 0;
  for (;;) {
    const auto comma = value.find(',', start);
    items.push_back(trimmed(value.substr(start, comma - start)));
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

// Why `item` is not a number, or "" where it is one (then in `number`): strtod must read all of
// it ("1x" and "" are not numbers) without overflow (1e999 would become inf). An underflow (glibc
// sets ERANGE for 1e-310, which a double holds as a subnormal, and for 1e-999, read as 0) is the
// nearest double, as for any other decimal.
std::string read_number(const std::string& item, double& number) {
  if (item.empty()) return "is empty (allowed: numbers, comma separated)";
  char* end = nullptr;
  errno = 0;
  number = std::strtod(item.c_str(), &end);
  if (end != item.c_str() + item.size()) return "is not a number";
  if (errno == ERANGE && std::isinf(number)) return "is beyond the range of a double";
  return {};
}

// The refusal of item i of `value`'s `count` items: the value alone where it is the only item.
std::string refusal(const std::string& value, std::size_t count, std::size_t i,
                    const std::string& item, const std::string& why) {
  if (count == 1 && item.empty()) {
    return "an empty value is not allowed (allowed: numbers, comma separated)";
  }
  std::string text =
      count == 1 ? "'" + value + "'" : "item " + std::to_string(i + 1) + " of '" + value + "'";
  if (count > 1 && !item.empty()) text += " ('" + item + "')";
  text += ' ';
  text += why;
  return text;
}

}  // namespace

std::vector<double> parse_number_list(const std::string& option,
                                      const std::vector<std::string>& values) {
  std::vector<double> numbers;
  for (const std::string& value : values) {
    const std::vector<std::string> items = items_of(value);
    for (std::size_t i = 0; i < items.size(); ++i) {
      double number = 0.0;
      const std::string why = read_number(items[i], number);
      if (!why.empty()) {
        throw ParameterError(option + ": " + refusal(value, items.size(), i, items[i], why));
      }
      numbers.push_back(number);
    }
  }
  return numbers;
}

}  // namespace hmfnet::cli
