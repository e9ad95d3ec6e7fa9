#include "framework/core/text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace hystbench {

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : separator) + s;
  return out;
}

std::string number_text(double v) {
  // Whole numbers read better in full: 100000, not 1e+05.
  if (v == std::trunc(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

std::size_t index_of_name(const std::vector<std::string>& names, const std::string& name,
                          const std::string& what) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw std::invalid_argument("unknown " + what + " '" + name + "'; valid: " + join(names));
  return static_cast<std::size_t>(it - names.begin());
}

}  // namespace hystbench
