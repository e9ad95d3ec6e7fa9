#include "framework/io/mat_file.hpp"

#include <matio.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <mutex>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {
namespace fs = std::filesystem;

// matio reports to stderr unless told otherwise; its words would stand
// beside ours, so they are dropped and our message says what is wrong.
void quiet_log(int, char*) {}
void silence_matio() {
  static std::once_flag once;
  std::call_once(once, [] { Mat_LogInitFunc("hystbench", quiet_log); });
}

struct VarDeleter {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using VarPtr = std::unique_ptr<matvar_t, VarDeleter>;

// One step of a path: a field name, or an element k (1-based) when name is empty.
struct Step {
  std::string name;
  std::size_t element = 0;
};

std::vector<Step> parse_path(const std::string& path, const std::string& file) {
  const auto bad = [&] {
    throw InputError(file + ": '" + path + "' is not a variable path; write a name, then .field "
                     "or (k) into structs, e.g. rec.Y(2).Data");
  };
  std::vector<Step> steps;
  std::size_t i = 0;
  const auto read_name = [&] {
    std::string name;
    while (i < path.size() && path[i] != '.' && path[i] != '(') name += path[i++];
    if (name.empty()) bad();
    steps.push_back({name, 0});
  };
  read_name();
  while (i < path.size()) {
    if (path[i] == '.') {
      ++i;
      read_name();
      continue;
    }
    const auto close = path.find(')', i);
    if (close == std::string::npos) bad();
    const std::string digits = path.substr(i + 1, close - i - 1);
    // 18 digits: beyond any array, and within std::stoul.
    if (digits.empty() || digits.size() > 18 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      bad();
    const std::size_t k = std::stoul(digits);
    if (k == 0) bad();
    steps.push_back({"", k});
    i = close + 1;
  }
  return steps;
}

std::size_t element_count(const matvar_t* v) {
  std::size_t n = 1;
  for (int d = 0; d < v->rank; ++d) n *= v->dims[d];
  return n;
}

std::string shape(const matvar_t* v) {
  std::string s;
  for (int d = 0; d < v->rank; ++d) s += (d ? "×" : "") + std::to_string(v->dims[d]);
  return s;
}

std::string field_list(matvar_t* v) {
  std::string out;
  const unsigned n = Mat_VarGetNumberOfFields(v);
  char* const* names = Mat_VarGetStructFieldnames(v);
  for (unsigned f = 0; f < n; ++f) out += std::string(out.empty() ? "" : ", ") + names[f];
  return out.empty() ? "none" : out;
}

// What a non-numeric variable is, and what to save instead.
std::string not_numbers(matvar_t* v) {
  switch (v->class_type) {
    case MAT_C_STRUCT: return "is a struct; name one of its fields (" + field_list(v) + "), e.g. with .Data";
    case MAT_C_CELL: return "is a cell array; save the numbers as a vector";
    case MAT_C_CHAR: return "is text, not numbers";
    case MAT_C_SPARSE: return "is a sparse matrix; save full(x)";
    case MAT_C_EMPTY: return "is empty; it needs one value per sample";
    case MAT_C_FUNCTION: return "is a function handle, not numbers";
    case MAT_C_OBJECT: case MAT_C_OPAQUE:
      return "is a MATLAB object (a timeseries or Simulink.SimulationOutput?); save its numbers "
             "as vectors or a struct (docs/formats.md#mat-files)";
    default:
      return v->isLogical ? "is logical (true/false); save double(x)"
                          : "is of a class hystbench cannot read; save it as double";
  }
}

bool numeric(const matvar_t* v) {
  switch (v->class_type) {
    case MAT_C_DOUBLE: case MAT_C_SINGLE: case MAT_C_INT8: case MAT_C_UINT8: case MAT_C_INT16:
    case MAT_C_UINT16: case MAT_C_INT32: case MAT_C_UINT32: case MAT_C_INT64: case MAT_C_UINT64:
      return !v->isLogical;
    default: return false;
  }
}

template <class T>
void copy_as_double(const void* data, Eigen::VectorXd& out) {
  const T* p = static_cast<const T*>(data);
  for (Eigen::Index i = 0; i < out.size(); ++i) out[i] = double(p[i]);
}

bool to_doubles(const matvar_t* v, Eigen::VectorXd& out) {
  switch (v->data_type) {
    case MAT_T_DOUBLE: copy_as_double<double>(v->data, out); return true;
    case MAT_T_SINGLE: copy_as_double<float>(v->data, out); return true;
    case MAT_T_INT8: copy_as_double<std::int8_t>(v->data, out); return true;
    case MAT_T_UINT8: copy_as_double<std::uint8_t>(v->data, out); return true;
    case MAT_T_INT16: copy_as_double<std::int16_t>(v->data, out); return true;
    case MAT_T_UINT16: copy_as_double<std::uint16_t>(v->data, out); return true;
    case MAT_T_INT32: copy_as_double<std::int32_t>(v->data, out); return true;
    case MAT_T_UINT32: copy_as_double<std::uint32_t>(v->data, out); return true;
    case MAT_T_INT64: copy_as_double<std::int64_t>(v->data, out); return true;
    case MAT_T_UINT64: copy_as_double<std::uint64_t>(v->data, out); return true;
    default: return false;
  }
}

// Character k of a char array (column-major), ASCII; MATLAB writes UTF-16.
char char_at(const matvar_t* v, std::size_t k) {
  if (v->data_type == MAT_T_UINT16 || v->data_type == MAT_T_UTF16) {
    const auto c = static_cast<const std::uint16_t*>(v->data)[k];
    return c < 128 ? char(c) : '?';
  }
  return static_cast<const char*>(v->data)[k];
}

// The rows of a char matrix, trailing blanks dropped (MATLAB pads them).
std::vector<std::string> rows_of(const matvar_t* v) {
  const std::size_t rows = v->rank == 2 ? v->dims[0] : 0, cols = v->rank == 2 ? v->dims[1] : 0;
  std::vector<std::string> out(rows);
  if (v->data == nullptr) return out;
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) out[r] += char_at(v, r + c * rows);
    out[r].erase(out[r].find_last_not_of(' ') + 1);
  }
  return out;
}

}  // namespace

struct MatReader::Handle {
  mat_t* mat = nullptr;
  std::vector<std::string> variables;
  ~Handle() {
    if (mat) Mat_Close(mat);
  }
};

bool has_mat_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".mat";
}

bool is_mat_file(const fs::path& path) {
  if (has_mat_extension(path)) return true;
  std::ifstream in(path, std::ios::binary);
  char head[6] = {};
  in.read(head, sizeof head);
  return in.gcount() == 6 && std::string(head, 6) == "MATLAB";
}

MatReader::MatReader(const fs::path& path)
    : name_(path.string()), handle_(std::make_unique<Handle>()) {
  silence_matio();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw MissingFileError(name_ + ": file not found; check the path (a relative path starts at the "
                             "current folder)");
  handle_->mat = Mat_Open(name_.c_str(), MAT_ACC_RDONLY);
  if (handle_->mat == nullptr)
    throw InputError(name_ + ": not a MAT file that can be read (MATLAB v5, v7 or v7.3 expected); "
                             "save it again with save(file, '-v7'), or give a CSV measurement");
  while (VarPtr v{Mat_VarReadNextInfo(handle_->mat)})
    if (v->name) handle_->variables.emplace_back(v->name);
}

MatReader::~MatReader() = default;

bool MatReader::has(const std::string& path) const {
  const auto steps = parse_path(path, name_);
  for (const auto& v : handle_->variables)
    if (v == steps.front().name) return true;
  return false;
}

namespace {

// Walks `steps` from the variable `top` down to what they name.
matvar_t* walk(matvar_t* top, const std::vector<Step>& steps, const std::string& path,
               const std::string& file) {
  matvar_t* v = top;
  std::string at = steps.front().name;
  std::size_t element = 0;
  bool picked = false;
  const auto fail = [&](const std::string& what) -> matvar_t* {
    throw InputError(file + ": '" + path + "': " + at + " " + what);
  };
  for (std::size_t s = 1; s < steps.size(); ++s) {
    const Step& step = steps[s];
    if (step.name.empty()) {
      if (step.element > element_count(v))
        fail("has " + std::to_string(element_count(v)) + " elements, not " +
             std::to_string(step.element));
      if (v->class_type == MAT_C_CELL) {
        v = Mat_VarGetCell(v, int(step.element - 1));
        if (v == nullptr) fail("(" + std::to_string(step.element) + ") is empty");
        picked = false;
        element = 0;
      } else if (v->class_type == MAT_C_STRUCT) {
        element = step.element - 1;
        picked = true;
      } else {
        fail("is not a struct or cell array; (k) picks an element of those only");
      }
      at.append("(").append(std::to_string(step.element)).append(")");
      continue;
    }
    if (v->class_type != MAT_C_STRUCT) fail("is not a struct; it has no field '" + step.name + "'");
    if (element_count(v) == 0) fail("is an empty struct");
    if (element_count(v) > 1 && !picked)
      fail("is a " + shape(v) + " struct array; pick one element, e.g. " + at + "(1)." + step.name);
    matvar_t* field = Mat_VarGetStructFieldByName(v, step.name.c_str(), element);
    if (field == nullptr) fail("has no field '" + step.name + "'; its fields: " + field_list(v));
    v = field;
    at += "." + step.name;
    picked = false;
    element = 0;
  }
  if (v == nullptr) fail("is empty");
  return v;
}

std::string variable_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
  return out.empty() ? "none" : out;
}

}  // namespace

Eigen::VectorXd MatReader::vector(const std::string& path, const std::string& role,
                                  int* digits) const {
  const auto steps = parse_path(path, name_);
  if (!has(path))
    throw InputError(name_ + ": no variable '" + steps.front().name + "' (for " + role +
                     "); its variables are " + variable_list(handle_->variables) +
                     ". Tell which hold t, u and y with the --columns option, e.g. "
                     "--columns t=time,u=v_in,y=x_out (a struct field as rec.X.Data)");
  VarPtr top(Mat_VarRead(handle_->mat, steps.front().name.c_str()));
  if (!top)
    throw InputError(name_ + ": the variable '" + steps.front().name + "' (for " + role +
                     ") is there but cannot be read (a MATLAB class matio does not know, or a "
                     "damaged file); save it again as double");
  const matvar_t* v = walk(top.get(), steps, path, name_);
  const std::string what = name_ + ": '" + path + "' (for " + role + ") ";
  if (!numeric(v)) throw InputError(what + not_numbers(const_cast<matvar_t*>(v)));
  if (v->isComplex)
    throw InputError(what + "is complex; save its real part, e.g. " + steps.front().name +
                     " = real(" + steps.front().name + ")");
  const std::size_t n = element_count(v);
  if (n == 0) throw InputError(what + "is empty; it needs one value per sample");
  if (v->rank != 2 || (v->dims[0] != 1 && v->dims[1] != 1))
    throw InputError(what + "is a " + shape(v) + " array; t, u and y must be vectors (one row "
                            "or one column), e.g. " + steps.front().name + "(:, 1)");
  Eigen::VectorXd out(static_cast<Eigen::Index>(n));
  if (v->data == nullptr || !to_doubles(v, out))
    throw InputError(what + "holds numbers of a type hystbench cannot read; save it as double");
  // Significant digits the stored numbers carry (the even-step check's tolerance).
  if (digits) *digits = v->data_type == MAT_T_SINGLE ? 7 : 17;
  return out;
}

std::optional<std::vector<std::string>> MatReader::labels(const std::string& path) const {
  if (!has(path)) return std::nullopt;
  const auto steps = parse_path(path, name_);
  VarPtr top(Mat_VarRead(handle_->mat, steps.front().name.c_str()));
  if (!top) return std::nullopt;
  matvar_t* v = walk(top.get(), steps, path, name_);
  if (v->class_type == MAT_C_CHAR) return rows_of(v);
  std::vector<std::string> out;
  if (v->class_type == MAT_C_CELL) {
    for (std::size_t i = 0; i < element_count(v); ++i) {
      const matvar_t* cell = Mat_VarGetCell(v, int(i));
      if (cell == nullptr || cell->class_type != MAT_C_CHAR)
        throw InputError(name_ + ": '" + path + "' (for segment): cell " + std::to_string(i + 1) +
                         " is not text; segment labels are a cell array of text or a vector");
      const auto rows = rows_of(cell);
      out.push_back(rows.empty() ? std::string() : rows.front());
    }
    return out;
  }
  const Eigen::VectorXd numbers = vector(path, "segment");
  for (const double x : numbers) out.push_back(number_text(x));
  return out;
}

namespace {


void write_vector(mat_t* mat, const std::string& name, const Eigen::VectorXd& values,
                  matio_compression compression) {
  std::size_t dims[2] = {std::size_t(values.size()), 1};
  VarPtr v(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                         const_cast<double*>(values.data()), MAT_F_DONT_COPY_DATA));
  if (!v || Mat_VarWrite(mat, v.get(), compression) != 0)
    throw InputError("cannot write the variable '" + name + "'");
}

// A char matrix, one padded row per label (cellstr() in MATLAB gives the
// cell array back). Not a cell array: matio 1.5.23 reads a v7.3 cell array
// in time quadratic in its length (minutes for 10 000 labels), and cannot
// read back the cell arrays it compresses itself.
void write_texts(mat_t* mat, const std::string& name, const std::vector<std::string>& texts,
                 matio_compression compression) {
  std::size_t width = 0;
  for (const auto& t : texts) width = std::max(width, t.size());
  const std::size_t rows = texts.size();
  std::string chars(rows * width, ' ');
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < texts[r].size(); ++c) chars[r + c * rows] = texts[r][c];
  std::size_t dims[2] = {rows, width};
  VarPtr v(Mat_VarCreate(name.c_str(), MAT_C_CHAR, MAT_T_UINT8, 2, dims, chars.data(), 0));
  if (!v || Mat_VarWrite(mat, v.get(), compression) != 0)
    throw InputError("cannot write the variable '" + name + "'");
}

}  // namespace

void write_mat_file(const fs::path& path,
                    const std::vector<std::pair<std::string, Eigen::VectorXd>>& vectors,
                    const std::vector<std::pair<std::string, std::vector<std::string>>>& texts,
                    MatFormat format) {
  silence_matio();
  const fs::path tmp = path.string() + ".tmp";
  const auto version = format == MatFormat::V73 ? MAT_FT_MAT73 : MAT_FT_MAT5;
  const auto compression = format == MatFormat::V7 ? MAT_COMPRESSION_ZLIB : MAT_COMPRESSION_NONE;
  try {
    mat_t* mat = Mat_CreateVer(tmp.string().c_str(), nullptr, version);
    if (!mat) throw InputError("cannot create the file");
    try {
      for (const auto& [name, values] : vectors) write_vector(mat, name, values, compression);
      for (const auto& [name, labels] : texts) write_texts(mat, name, labels, compression);
    } catch (...) {
      Mat_Close(mat);
      throw;
    }
    // Closing flushes (HDF5 writes on close): a failure is a failed write.
    if (Mat_Close(mat) != 0) throw InputError("writing the file failed (disk full?)");
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw InputError("cannot rename " + tmp.string() + " into place (" + ec.message() + ")");
  } catch (const InputError& e) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw InputError(path.string() + ": " + e.what() + "; check that the folder is writable");
  }
}

}  // namespace hystbench
