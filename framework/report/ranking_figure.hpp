#pragma once
// ranks.gp: the Friedman average ranks of the algorithms, best at the top,
// each with a bar of ±CD/2 (Nemenyi, alpha 0.05), so that two algorithms
// whose bars do not overlap differ significantly. Data in ranks.dat.
#include <filesystem>

#include "framework/report/friedman_ranking.hpp"

namespace hystbench {

// Returns the script path.
std::filesystem::path write_ranking_figure(const std::filesystem::path& dir,
                                           const FriedmanRanking& r);

}  // namespace hystbench
