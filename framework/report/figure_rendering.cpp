// Running gnuplot on the figure scripts: finding it on the PATH, and
// reporting the first error of a script that fails.
#include "framework/report/figure_rendering.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace hystbench {
namespace fs = std::filesystem;
namespace {

constexpr const char* kImageTypes[] = {".svg", ".png", ".pdf"};

bool gnuplot_on_path() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string d; std::getline(dirs, d, ':');) {
    const fs::path exe = fs::path(d.empty() ? "." : d) / "gnuplot";
    std::error_code ec;
    if (fs::is_regular_file(exe, ec) && ::access(exe.c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The line worth showing from one script's messages (those after byte
// `from` of the log): the first that is not a warning, as gnuplot stops at
// its first error; else the first line.
std::string first_error_line(const fs::path& log, std::uintmax_t from) {
  std::ifstream in(log);
  in.seekg(std::streamoff(from));
  std::string first;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.find("warning:") == std::string::npos) return line;
    if (first.empty()) first = line;
  }
  return first;
}

}  // namespace

std::vector<fs::path> render_figures(const fs::path& dir, const std::vector<fs::path>& scripts,
                                     std::string& note) {
  note.clear();
  std::vector<fs::path> images;
  if (!gnuplot_on_path()) {
    note = "gnuplot not found: install gnuplot (Debian: apt-get install gnuplot-nox), then run "
           "`gnuplot NAME.gp` inside " + dir.string();
    return images;
  }
  const fs::path log = dir / "gnuplot.log";
  std::error_code ec;
  fs::remove(log, ec);
  for (const auto& script : scripts) {
    const fs::path name = script.filename();
    for (const char* ext : kImageTypes)  // so that only fresh images are returned
      fs::remove(dir / fs::path(name).replace_extension(ext), ec);
    const std::uintmax_t log_before = fs::exists(log, ec) ? fs::file_size(log, ec) : 0;
    const std::string command = "cd " + shell_quote(dir.string()) + " && gnuplot " +
                                shell_quote(name.string()) + " 2>> gnuplot.log";
    if (std::system(command.c_str()) != 0 && note.empty())
      note = "gnuplot failed on " + name.string() + ": " + first_error_line(log, log_before) +
             " (see " + log.string() + ")";
    for (const char* ext : kImageTypes) {
      const fs::path image = dir / fs::path(name).replace_extension(ext);
      if (fs::exists(image, ec) && fs::file_size(image, ec) > 0) images.push_back(image);
    }
  }
  if (fs::exists(log, ec) && fs::file_size(log, ec) == 0) fs::remove(log, ec);
  return images;
}

}  // namespace hystbench
