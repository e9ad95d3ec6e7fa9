#pragma once
// What the fitting commands print about a fit.
#include <string>

#include "framework/discovery/comparison.hpp"
#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/fit_record.hpp"

namespace hystbench::cli {

// A number as printed for people: four significant digits, then the unit
// (files keep every digit).
std::string quantity(double x, const std::string& unit);

// The model and one line per parameter: name, physical value, unit.
void print_parameters(const FitRecord& r);
// RMSE on the estimation and held-out samples.
void print_errors(const FitErrors& e, const std::string& unit);
// RMSE and fit % on each part of a comparison, and the noise floor.
void print_comparison_headline(const Comparison& metrics, const std::string& unit);

}  // namespace hystbench::cli
