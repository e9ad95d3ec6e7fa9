#pragma once
// The check of an option that names a MAT file to write (--mat, --out of
// simulate when it ends in .mat): refused at parse time, before any work.
#include <CLI/CLI.hpp>
#include <string>

#include "framework/io/mat_file.hpp"

namespace hystbench::cli {

inline CLI::Validator mat_file_name(const std::string& option) {
  return CLI::Validator(
      [option](const std::string& value) -> std::string {
        if (has_mat_extension(value)) return {};
        return option + " " + value + ": a MAT file's name ends in .mat";
      },
      "FILE.mat");
}

}  // namespace hystbench::cli
