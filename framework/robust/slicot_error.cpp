#include "framework/robust/slicot_error.hpp"

#include <cstddef>

namespace {

thread_local std::string last_report;

}  // namespace

// Linked into the program, this definition takes the place of LAPACK's.
extern "C" void xerbla_(const char* name, const int* info, std::size_t length) {
  std::string routine(name, length);
  while (!routine.empty() && routine.back() == ' ') routine.pop_back();
  last_report = routine + ": argument " + std::to_string(*info) + " is invalid";
}

namespace hystbench::robust {

std::string take_argument_error(const std::string& routine, int info) {
  std::string report = last_report.empty() ? routine + ": argument " + std::to_string(-info) + " is invalid"
                                            : last_report;
  last_report.clear();
  return report;
}

}  // namespace hystbench::robust
