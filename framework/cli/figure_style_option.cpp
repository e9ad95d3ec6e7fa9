#include "framework/cli/commands.hpp"
#include "framework/report/figure_style.hpp"

namespace hystbench::cli {

void add_figure_style_option(CLI::App& command) {
  command
      .add_option_function<std::string>(
          "--figure-style",
          [](const std::string& s) { gnuplot::set_figure_style(gnuplot::parse_figure_style(s, "--figure-style")); },
          "screen (default: titled, for a monitor) or paper (no title, 8.5 cm single or 17.5 cm double "
          "column, 8 pt text, PNG at 300 dpi)")
      ->check(CLI::IsMember({"screen", "paper"}));
}

}  // namespace hystbench::cli
