#include "framework/io/header_names.hpp"

#include <gtest/gtest.h>

namespace hystbench {
namespace {

TEST(HeaderNames, UnitsAreSplitFromTheNamesLabsWrite) {
  const std::pair<const char*, HeaderName> cases[] = {
      {"Voltage [V]", {"Voltage", "V"}},     {"Weg (µm)", {"Weg", "µm"}},
      {"displacement_um", {"displacement", "µm"}}, {"t/ms", {"t", "ms"}},
      {"time s", {"time", "s"}},             {"input_signal", {"input_signal", ""}},
      {"u", {"u", ""}},                      {"force [kN]", {"force", "kN"}},
      {" y_m ", {"y", "m"}},                 {"temperature (degC)", {"temperature", "degC"}},
  };
  for (const auto& [name, expected] : cases) {
    const HeaderName h = split_unit(name);
    EXPECT_EQ(h.base, expected.base) << name;
    EXPECT_EQ(h.unit, expected.unit) << name;
  }
}

TEST(HeaderNames, RolesAreKnownByEnglishAndGermanNames) {
  const std::vector<std::string> names = {"Zeit [s]", "Spannung [V]", "Weg [um]", "Temperatur"};
  EXPECT_EQ(columns_named_as(names, ColumnRole::t), std::vector<std::size_t>{0});
  EXPECT_EQ(columns_named_as(names, ColumnRole::u), std::vector<std::size_t>{1});
  EXPECT_EQ(columns_named_as(names, ColumnRole::y), std::vector<std::size_t>{2});
  const std::vector<std::string> two = {"TIME", "input", "Voltage_V", "position (mm)"};
  EXPECT_EQ(columns_named_as(two, ColumnRole::u), (std::vector<std::size_t>{1, 2}));
  EXPECT_TRUE(columns_named_as({"a", "b"}, ColumnRole::y).empty());
}

}  // namespace
}  // namespace hystbench
