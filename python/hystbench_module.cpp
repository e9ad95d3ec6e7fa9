// hystbench._core: the commands of the `hystbench` program run in process,
// and the readers a notebook needs. The Python side (hystbench/__init__.py)
// turns the files the commands write into Python objects.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "framework/cli/commands.hpp"
#include "framework/core/error.hpp"
#include "framework/io/mat_file.hpp"
#include "framework/io/measurement.hpp"

namespace py = pybind11;

namespace {

// Sends std::cout (and std::cerr: progress lines) into one string for the
// life of a command, unless the caller wants to see them.
class CapturedOutput {
 public:
  explicit CapturedOutput(bool echo) : echo_(echo) {
    if (echo_) return;
    out_ = std::cout.rdbuf(text_.rdbuf());
    err_ = std::cerr.rdbuf(text_.rdbuf());
  }
  ~CapturedOutput() {
    if (echo_) return;
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  std::string text() const { return text_.str(); }

 private:
  bool echo_;
  std::ostringstream text_;
  std::streambuf* out_ = nullptr;
  std::streambuf* err_ = nullptr;
};

// Runs `hystbench ARGS...`; returns what it printed. Bad input raises
// InputError (a ValueError) with the program's one-line message. One
// command at a time: the output capture swaps the process's std::cout, and
// plugin loading fills process-wide registries.
std::string run_command(const std::vector<std::string>& args, bool echo) {
  static std::mutex one_at_a_time;
  CLI::App app{"hystbench"};
  app.require_subcommand(1);
  const auto commands = hystbench::cli::add_all_commands(app);
  std::vector<std::string> words{"hystbench"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  py::gil_scoped_release unlocked;  // before the lock: a waiting thread holds no GIL
  const std::lock_guard<std::mutex> lock(one_at_a_time);
  CapturedOutput output(echo);
  try {
    app.parse(int(argv.size()), argv.data());
  } catch (const CLI::Success&) {  // --help: that of the innermost command given
    const CLI::App* asked = &app;
    while (!asked->get_subcommands().empty()) asked = asked->get_subcommands().back();
    return asked->help();
  } catch (const CLI::ParseError& e) {
    throw hystbench::InputError(e.what());
  }
  for (const auto& [command, action] : commands)
    if (command->parsed()) action();
  return output.text();
}

py::dict measurement_dict(const hystbench::Measurement& m) {
  py::dict d;
  d["t"] = m.t;
  d["u"] = m.u;
  d["y"] = m.y;
  d["segment"] = m.segment;
  d["sample_time"] = m.sample_time;
  d["source"] = m.source;
  d["u_unit"] = m.u_unit;
  d["y_unit"] = m.y_unit;
  return d;
}

py::dict read_measurement(const std::string& path, const std::string& columns,
                          const std::string& delimiter) {
  auto map = hystbench::ColumnMap::parse(columns);
  map.delimiter = hystbench::ColumnMap::parse_delimiter(delimiter);
  return measurement_dict(hystbench::read_measurement(path, map));
}

Eigen::VectorXd read_mat_vector(const std::string& path, const std::string& name) {
  return hystbench::MatReader(path).vector(name, name);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "hystbench's commands and readers, in process (use the hystbench package)";
  py::register_exception<hystbench::InputError>(m, "InputError", PyExc_ValueError);
  m.def("run_command", &run_command, py::arg("args"), py::arg("echo") = false);
  m.def("read_measurement", &read_measurement, py::arg("path"), py::arg("columns") = "",
        py::arg("delimiter") = "auto");
  m.def("read_mat_vector", &read_mat_vector, py::arg("path"), py::arg("name"));
  m.attr("version") = HYSTBENCH_VERSION;
}
