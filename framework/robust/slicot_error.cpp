#include "framework/robust/slicot_error.hpp"

#include <algorithm>
#include <cstddef>

namespace {

thread_local std::string last_report;

}  // namespace

// Linked into the program, this definition takes the place of LAPACK's.
// No exception may unwind through the Fortran frames that called it.
extern "C" void xerbla_(const char* name, const int* info, std::size_t length) noexcept {
  try {
    std::string routine(name, std::min<std::size_t>(length, 32));
    while (!routine.empty() && routine.back() == ' ') routine.pop_back();
    last_report = routine + ": argument " + std::to_string(*info) + " is invalid";
  } catch (...) {
    last_report.clear();
  }
}

namespace hystbench::robust {

std::string take_argument_error(const std::string& routine, int info) {
  std::string report = last_report.empty() ? routine + ": argument " + std::to_string(-info) + " is invalid"
                                            : last_report;
  last_report.clear();
  return report;
}

}  // namespace hystbench::robust
