#include "framework/report/markdown.hpp"

#include <cmath>
#include <cstdio>

namespace hystbench::markdown {

std::string num(double x) {
  if (!std::isfinite(x)) return "–";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string num(const nlohmann::json& j) { return j.is_number() ? num(j.get<double>()) : "–"; }

std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out.empty() ? " " : out;
}

std::string row(const std::vector<std::string>& cells) {
  std::string out = "|";
  for (const auto& c : cells) out += " " + cell(c) + " |";
  return out + "\n";
}

std::string header_row(const std::vector<std::string>& cells, const std::string& align) {
  std::string rule = "|";
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const bool left = align.empty() ? k == 0 : align.at(k) == 'l';
    rule += left ? " :-- |" : " --: |";
  }
  return row(cells) + rule + "\n";
}

}  // namespace hystbench::markdown
