#include "framework/report/figure_style.hpp"

#include <atomic>

#include "framework/core/error.hpp"

namespace hystbench::gnuplot {
namespace {
std::atomic<FigureStyle> g_style{FigureStyle::Screen};
}

void set_figure_style(FigureStyle style) { g_style = style; }
FigureStyle figure_style() { return g_style; }

// Screen: about 800 px of data area at about 7 px a character. Paper: 7 or
// 16 cm of data area at about 1.55 mm a character of 8 pt Helvetica.
double characters_across(bool tall) {
  if (figure_style() == FigureStyle::Screen) return 110;
  return tall ? 100 : 45;
}

bool key_needs_double_column(const std::vector<std::string>& titles) {
  double characters = 0;
  for (const auto& title : titles) characters += double(title.size()) + 6;  // the sample line and a gap
  return characters > 2 * characters_across();
}

FigureStyle parse_figure_style(const std::string& text, const std::string& where) {
  if (text == "screen") return FigureStyle::Screen;
  if (text == "paper") return FigureStyle::Paper;
  throw InputError(where + " \"" + text + "\": give screen (the default) or paper (no title, 8.5 or 17.5 cm wide)");
}

}  // namespace hystbench::gnuplot
