#pragma once
// Where a file named in an experiment lives: as given (relative to the
// current folder), else relative to the experiment file's folder or one of
// the folders above it. The bundled experiments sit in
// benchmarks/experiments/ and name their data from the repository root, so
// they run, and their results folders report, from any current folder.
#include <filesystem>
#include <string>

namespace hystbench {

// Throws InputError naming `key` and the places looked in.
std::filesystem::path resolve_data_path(const std::string& name,
                                        const std::filesystem::path& base_dir,
                                        const std::string& key);

}  // namespace hystbench
