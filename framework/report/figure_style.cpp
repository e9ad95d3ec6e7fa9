#include "framework/report/figure_style.hpp"

#include <atomic>

#include "framework/core/error.hpp"

namespace hystbench::gnuplot {
namespace {
std::atomic<FigureStyle> g_style{FigureStyle::Screen};
}

void set_figure_style(FigureStyle style) { g_style = style; }
FigureStyle figure_style() { return g_style; }

FigureStyle parse_figure_style(const std::string& text, const std::string& where) {
  if (text == "screen") return FigureStyle::Screen;
  if (text == "paper") return FigureStyle::Paper;
  throw InputError(where + " \"" + text + "\": give screen (the default) or paper (no title, 8.5 or 17.5 cm wide)");
}

}  // namespace hystbench::gnuplot
