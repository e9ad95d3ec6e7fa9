#pragma once
// Whole-file writes that never leave a half-written file behind: the text
// goes to a temporary file in the same folder, which is then renamed.
#include <filesystem>
#include <string>

namespace hystbench {

// Throws InputError naming the path when it cannot be written.
void write_file_atomic(const std::filesystem::path& path, const std::string& content);

}  // namespace hystbench
