#include "framework/cli/fit_summary.hpp"

#include <iomanip>
#include <iostream>

#include "framework/report/table_format.hpp"

namespace hystbench::cli {

std::string quantity(double x, const std::string& unit) {
  const std::string number = table::format_fitness(x, table::Format::Markdown);
  return unit.empty() ? number : number + " " + unit;
}

void print_parameters(const FitRecord& r) {
  std::cout << "model " << r.model.text() << "\n";
  for (const auto& p : r.parameters_json())
    std::cout << "  " << std::left << std::setw(28) << p["name"].get<std::string>() << " "
              << std::setw(14) << p["value"].get<double>() << " "
              << p["unit"].get<std::string>() << "\n";
}

void print_errors(const FitErrors& e, const std::string& unit) {
  std::cout << "RMSE " << e.rmse_estimation << " " << unit << " on " << e.n_estimation
            << " estimation samples";
  if (e.n_heldout) std::cout << ", " << e.rmse_heldout << " " << unit << " on " << e.n_heldout
                             << " held-out samples";
  std::cout << "\n";
}

}  // namespace hystbench::cli
