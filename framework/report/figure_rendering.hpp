#pragma once
// Rendering of the figure scripts, apart from writing them: a script stays
// usable without gnuplot, which only the rendering needs.
#include <filesystem>
#include <string>
#include <vector>

namespace hystbench {

// Runs gnuplot on each script inside `dir`. Returns the rendered image paths.
// When gnuplot is not installed, renders nothing and sets `note` to one line
// saying how to render them later.
std::vector<std::filesystem::path> render_figures(const std::filesystem::path& dir,
                                                  const std::vector<std::filesystem::path>& scripts,
                                                  std::string& note);

}  // namespace hystbench
