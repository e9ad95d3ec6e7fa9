#pragma once
// Whole-file writes that never leave a half-written file behind: the text
// goes to a temporary file in the same folder, which is then renamed.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hystbench {

// Throws InputError naming the path when it cannot be written.
void write_file_atomic(const std::filesystem::path& path, const std::string& content);

// Writes each (name, text) into `dir`; returns the paths in order.
std::vector<std::filesystem::path> write_files_atomic(
    const std::filesystem::path& dir, const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace hystbench
