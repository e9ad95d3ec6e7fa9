#pragma once
// Small text helpers shared by messages and listings.
#include <string>
#include <vector>

namespace hystbench {

// "a, b, c"
std::string join(const std::vector<std::string>& items, const std::string& separator = ", ");

// Shortest text that reads back as the same double: 5 -> "5", 5.12 -> "5.12",
// 100000 -> "100000".
std::string number_text(double v);

// One number through a printf format ("%.3g", "%.1f"), for sentences in
// reports.
std::string format_number(const char* format, double v);
// The current time by strftime's `format`, in UTC or in local time.
std::string time_now(const char* format, bool utc);

// Position of `name` in `names`; throws std::invalid_argument naming `what`
// and the valid names. Used to map option strings to enums.
std::size_t index_of_name(const std::vector<std::string>& names, const std::string& name,
                          const std::string& what);

// The name in `names` that `typed` most likely misspells (one edit away, or
// two for names longer than four letters; a swap of neighbours is one edit),
// or "" when none is that close. For "did you mean" in messages.
std::string closest_name(const std::vector<std::string>& names, const std::string& typed);

}  // namespace hystbench
