#include "framework/report/table_format.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace hystbench::table {
namespace {

std::string printf_string(const char* format, double x, int precision = -1) {
  char buf[64];
  if (precision < 0)
    std::snprintf(buf, sizeof buf, format, x);
  else
    std::snprintf(buf, sizeof buf, format, precision, x);
  return buf;
}

}  // namespace

std::string non_finite(double x, Format f) {
  const bool md = f == Format::Markdown;
  if (std::isnan(x)) return md ? "—" : "--";
  const std::string sign = x < 0 ? "-" : "";
  return md ? sign + "∞" : "$" + sign + "\\infty$";
}

// Four significant digits. Rounding first (through %.3e) decides the
// notation from the printed value, so 9999.7 becomes 1.000e+04, not 10000.
std::string format_fitness(double x, Format f) {
  if (!std::isfinite(x)) return non_finite(x, f);
  if (x == 0.0) return "0";
  const std::string sci = printf_string("%.3e", x);
  const auto e_pos = sci.find('e');
  const int exponent = std::atoi(sci.c_str() + e_pos + 1);
  if (exponent < -3 || exponent >= 4) {
    if (f == Format::Markdown) return sci;
    // std::string("$") first: `"$" + temporary` trips a false -Wrestrict in GCC 12.
    return std::string("$") + sci.substr(0, e_pos) + "\\times10^{" + std::to_string(exponent) +
           "}$";
  }
  const std::string fixed = printf_string("%.*f", x, 3 - exponent);
  return (f == Format::Latex && x < 0) ? "$" + fixed + "$" : fixed;
}

// Mean iterations and evaluations per trial: whole numbers stay whole.
std::string format_count(double x, Format f) {
  if (!std::isfinite(x)) return non_finite(x, f);
  if (x == std::round(x)) return printf_string("%.0f", x);
  return printf_string("%.1f", x);
}

std::string bold(const std::string& cell, Format f) {
  if (f == Format::Markdown) return "**" + cell + "**";
  // \textbf does not reach into math mode; \boldmath does.
  const bool math = cell.find('$') != std::string::npos;
  return std::string("\\textbf{") + (math ? "\\boldmath" : "") + cell + "}";
}

std::string bold_if_best(const std::string& cell, const std::string& best_text, Format f) {
  return !best_text.empty() && cell == best_text ? bold(cell, f) : cell;
}

std::string significance_level(double alpha, Format f) {
  char level[32];
  std::snprintf(level, sizeof level, "%g", alpha);
  return f == Format::Markdown ? std::string("α = ") + level
                                : std::string("$\\alpha = ") + level + "$";
}

std::string escape_latex(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '_': case '%': case '&': case '#': case '$': case '{': case '}':
        out += '\\';
        out += c;
        break;
      case '\\': out += "\\textbackslash{}"; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      default: out += c;
    }
  }
  // The one non-ASCII sign the tables write: math mode needs no input encoding.
  const std::string times = "×";
  for (auto at = out.find(times); at != std::string::npos; at = out.find(times, at))
    out.replace(at, times.size(), "$\\times$");
  return out;
}

std::string escape_markdown(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|' || c == '*' || c == '_' || c == '`' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

std::string escape(const std::string& s, Format f) {
  return f == Format::Markdown ? escape_markdown(s) : escape_latex(s);
}

// \label keys may not hold TeX specials; anything unusual becomes '-'.
std::string label_key(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ||
                       c == '.' || c == ':';
    out += plain ? c : '-';
  }
  return out;
}


}  // namespace hystbench::table
