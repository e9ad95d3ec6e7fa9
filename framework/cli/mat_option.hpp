#pragma once
// The check of an option that names a MAT file to write (--mat, --out of
// simulate when it ends in .mat): refused at parse time, before any work.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "framework/io/mat_file.hpp"

namespace hystbench::cli {

// CLI11 puts the option's name before the message ("--mat: out.csv: ...").
inline CLI::Validator mat_file_name() {
  return CLI::Validator(
      [](const std::string& value) -> std::string {
        if (!has_mat_extension(value)) return value + ": a MAT file's name ends in .mat";
        const auto folder = std::filesystem::path(value).parent_path();
        if (!folder.empty() && !std::filesystem::is_directory(folder))
          return value + ": the folder " + folder.string() +
                 " does not exist; create it or write the file elsewhere";
        return {};
      },
      "FILE.mat");
}

}  // namespace hystbench::cli
