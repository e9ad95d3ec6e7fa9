// libFuzzer target for the experiment-file loader (Experiment::parse, which
// Experiment::load reads files with). Bad input must end in an InputError;
// any other exception, a crash or a sanitizer report is a finding. An
// experiment that loads is written out with to_json and must load again to
// the same thing.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "framework/core/error.hpp"
#include "framework/harness/experiment.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  hystbench::Experiment e;
  try {
    e = hystbench::Experiment::parse(in, "fuzz.json");
  } catch (const hystbench::InputError&) {
    return 0;
  }
  const nlohmann::json written = e.to_json();
  const hystbench::Experiment again = hystbench::Experiment::from_json(written, "again");
  if (again.to_json() != written) std::abort();
  return 0;
}
