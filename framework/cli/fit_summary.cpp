#include "framework/cli/fit_summary.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>

#include "framework/discovery/noise_floor.hpp"
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

namespace {

void print_part(const char* name, const ErrorMetrics& m, const std::string& unit) {
  // fit % divides by the spread of y about its mean.
  const std::string fit = std::isfinite(m.fit_percent) ? "fit " + quantity(m.fit_percent, "%")
                                                       : "fit % not defined (y is constant)";
  std::cout << "  " << name << ": RMSE " << quantity(m.rmse, unit) << ", " << fit << ", " << m.n
            << " samples\n";
}

}  // namespace

void print_comparison_headline(const Comparison& metrics, const std::string& unit) {
  // Without a hold-out every sample is an estimation sample: "all" says it.
  if (metrics.parts.heldout) {
    print_part("estimation", metrics.parts.estimation, unit);
    print_part("heldout", *metrics.parts.heldout, unit);
  }
  print_part("all", metrics.parts.all, unit);
  const ComparedNoiseFloor& floor = metrics.noise_floor;
  if (std::isfinite(floor.sigma)) {
    std::cout << "  estimated noise sigma " << quantity(floor.sigma, unit);
    if (std::isfinite(floor.rmse_over_sigma))
      std::cout << " (RMSE / sigma " << quantity(floor.rmse_over_sigma, "") << ")";
    std::cout << "\n";
  } else {
    std::cout << "  noise sigma not estimated (fewer than " << kNoiseFloorFewestSamples
              << " samples)\n";
  }
  std::cout << "  " << metrics.excitation.summary() << "\n";
  if (metrics.startup.worth_saying()) std::cout << "  " << metrics.startup.sentence() << "\n";
}

}  // namespace hystbench::cli
