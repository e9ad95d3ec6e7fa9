#pragma once
// Reading a JSON file the user named, with the one message for each way it
// can fail.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace hystbench {

// Throws InputError "PATH: cannot open this WHAT; check the path" or
// "PATH: not valid JSON: ..." (a syntax error, or a number beyond a double).
nlohmann::json read_json_file(const std::filesystem::path& path, const std::string& what);

}  // namespace hystbench
