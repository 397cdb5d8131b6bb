#include "cli/number_list.hpp"

#include <cerrno>
#include <cstdlib>

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

// Why a non-empty `item` is not a number, or "" where it is one (then in `number`): strtod must
// read all of it ("1x" is not a number) without overflow or underflow (1e999 would become inf).
std::string read_number(const std::string& item, double& number) {
  char* end = nullptr;
  errno = 0;
  number = std::strtod(item.c_str(), &end);
  if (end != item.c_str() + item.size()) return "is not a number";
  if (errno == ERANGE) return "is beyond the range of a double";
  return {};
}

}  // namespace

std::vector<double> parse_number_list(const std::string& option,
                                      const std::vector<std::string>& values) {
  std::vector<double> numbers;
  for (const std::string& value : values) {
    const std::vector<std::string> items = items_of(value);
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::string place =
          items.size() == 1 ? "'" + value + "'"
                            : "item " + std::to_string(i + 1) + " of '" + value + "'";
      if (items[i].empty()) {
        throw CLI::ValidationError(
            option, (items.size() == 1 ? "an empty value is not allowed" : place + " is empty") +
                        " (allowed: numbers, comma separated)");
      }
      double number = 0.0;
      const std::string why = read_number(items[i], number);
      if (!why.empty()) {
        throw CLI::ValidationError(
            option, place + (items.size() == 1 ? "" : " ('" + items[i] + "')") + " " + why);
      }
      numbers.push_back(number);
    }
  }
  return numbers;
}

CLI::Option* add_number_list(CLI::App* command, const std::string& name,
                             std::vector<double>& target, const std::string& description) {
  return command
      ->add_option_function<std::vector<std::string>>(
          name,
          [name, &target](const std::vector<std::string>& values) {
            target = parse_number_list(name, values);
          },
          description)
      ->type_name("FLOAT,...");
}

}  // namespace hmfnet::cli
