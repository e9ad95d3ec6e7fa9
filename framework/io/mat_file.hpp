#pragma once
// MATLAB MAT files through matio: v5, v7 (compressed v5) and v7.3 (HDF5).
// Reading finds a numeric vector by a path into the file's variables
// ("u", "rec.Y(2).Data"), as measurements recorded by MATLAB, Simulink or
// dSPACE ControlDesk hold them; writing stores named column vectors.
#include "framework/core/eigen.hpp"
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hystbench {

enum class MatFormat { V5, V7, V73 };

// True when the file starts as a MAT file does ("MATLAB 5.0 MAT-file",
// "MATLAB 7.3 MAT-file"), or is named *.mat (so that a damaged one gets
// the MAT file's message, not the CSV reader's).
bool is_mat_file(const std::filesystem::path& path);
// Named *.mat (any case): what writers go by.
bool has_mat_extension(const std::filesystem::path& path);

// One open MAT file, read only. InputError naming the file when it is not a
// MAT file.
class MatReader {
 public:
  explicit MatReader(const std::filesystem::path& path);
  ~MatReader();
  MatReader(const MatReader&) = delete;
  MatReader& operator=(const MatReader&) = delete;

  // The real numeric vector at `path` (a variable, then ".field" and "(k)",
  // k from 1, into structs). InputError naming the file and the path when it
  // is absent (listing what there is), not numeric, complex, or not a vector.
  // `role` ("t", "u", ...) is said in the message. `digits`, when given,
  // gets the significant digits the stored numbers carry (7 for single).
  Eigen::VectorXd vector(const std::string& path, const std::string& role,
                         int* digits = nullptr) const;
  // Text labels at `path`: a cell array of text, a char matrix (a row per
  // label, trailing blanks dropped) or a numeric vector; nullopt when the
  // path names nothing.
  std::optional<std::vector<std::string>> labels(const std::string& path) const;
  bool has(const std::string& path) const;
  const std::string& name() const { return name_; }

 private:
  struct Handle;
  std::string name_;
  std::unique_ptr<Handle> handle_;
};

// Writes column vectors (and text labels, as char matrices) as a MAT file,
// through a temporary file renamed into place. InputError naming the path
// when it cannot be written.
void write_mat_file(const std::filesystem::path& path,
                    const std::vector<std::pair<std::string, Eigen::VectorXd>>& vectors,
                    const std::vector<std::pair<std::string, std::vector<std::string>>>& texts = {},
                    MatFormat format = MatFormat::V7);

}  // namespace hystbench
