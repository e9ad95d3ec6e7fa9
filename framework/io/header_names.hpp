#pragma once
// What a lab file's header names say: the unit written into a name
// ("displacement_um", "U [V]", "Weg (µm)", "t/s") and the role (t, u, y) of
// a column known by a common English or German name, so that files as a
// data-acquisition program saves them are read without --columns.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hystbench {

struct HeaderName {
  std::string base;  // the name without its unit
  std::string unit;  // empty when the name carries none; "um" is written µm
};

// "U [V]" and "U (V)": any text in the last brackets; "x_um", "x um" and
// "x/um": a known unit after the last '_', blank or '/'.
HeaderName split_unit(std::string_view name);

// The roles of a measurement file and the names each is known by.
enum class ColumnRole { t, u, y };
const char* role_name(ColumnRole role);
// "time, zeit, t, timestamp" for messages.
std::string role_synonyms(ColumnRole role);

// Indices of the columns whose name without its unit is a name of `role`
// (case-insensitive).
std::vector<std::size_t> columns_named_as(const std::vector<std::string>& names, ColumnRole role);

}  // namespace hystbench
