#pragma once
// The --out folder of the commands that write results (run, report, rank):
// checked before any input is read to the end, created only after.
#include <filesystem>
#include <string>

namespace hystbench {

// Refuses a path that is a file (a folder or nothing is fine).
void check_output_path(const std::filesystem::path& dir);

// Refuses a path that is a file, and a folder that already holds `marker`
// (what the command writes, e.g. "trials.jsonl") unless `replace` is set.
// `holds` names that content and `options` how to go on, for the message:
// "--out DIR: already holds <holds>; <options>, or choose another folder with --out".
void check_output_folder(const std::filesystem::path& dir, const std::string& marker, bool replace,
                         const std::string& holds, const std::string& options);

// Creates the folder (and its parents); InputError when that fails.
void create_output_folder(const std::filesystem::path& dir);

}  // namespace hystbench
