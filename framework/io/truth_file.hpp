#pragma once
// DATA.truth.json: what `hystbench simulate` knows about the data it wrote
// (true parameters, noise, units), read by whoever later fits those data.
#include <filesystem>
#include <nlohmann/json.hpp>

namespace hystbench {

// The truth file beside `data_file` (same name, extension .truth.json), or an
// empty object when there is none or it is not a JSON object.
nlohmann::json read_truth(const std::filesystem::path& data_file);

}  // namespace hystbench
