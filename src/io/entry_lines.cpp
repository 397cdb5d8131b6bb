#include "io/entry_lines.hpp"

#include <cstdio>

namespace hmfnet {

void write_entry_lines(std::ostream& out, const Network& network, Triangle triangle, int base) {
  char buffer[32];
  for (NodeIndex i = 0; i < network.size(); ++i) {
    for (const auto [j, w] : network.row(i)) {
      if (triangle == Triangle::lower ? j > i : j < i) continue;
      out << i + base << ' ' << j + base;
      if (network.weighted()) {
        std::snprintf(buffer, sizeof buffer, " %.17g", w);
        out << buffer;
      }
      out << '\n';
    }
  }
}

}  // namespace hmfnet
