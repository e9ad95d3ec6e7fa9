#pragma once
// Writing a comparison out: metrics.json, report.md and the figures.
#include <filesystem>
#include <string>
#include <vector>

#include "framework/discovery/comparison.hpp"

namespace hystbench {

// Writes metrics.json (to_json of `metrics`, comparison.hpp), report.md and
// the figures (gnuplot scripts, their data, and the images when gnuplot is
// installed; comparison_figures.hpp) into `dir`, created when missing.
// `title` heads the report, `model_text` describes the model (e.g.
// "hysteresis,asymmetry,msd"). Returns the files written.
std::vector<std::filesystem::path> write_comparison(const std::filesystem::path& dir,
                                                    const ComparisonInput& in,
                                                    const Comparison& metrics,
                                                    const std::string& title,
                                                    const std::string& model_text);

// The text of report.md. `figure_note` is one line shown under the
// figures (e.g. that gnuplot was missing); `images` says whether the
// rendered .png files exist to embed.
std::string comparison_markdown(const ComparisonInput& in, const Comparison& metrics,
                                const std::string& title, const std::string& model_text,
                                bool images, const std::string& figure_note);

}  // namespace hystbench
