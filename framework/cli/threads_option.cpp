#include "framework/cli/threads_option.hpp"

#include <omp.h>

#include "framework/cli/number_range.hpp"

namespace hystbench::cli {

void add_threads_option(CLI::App* cmd) {
  cmd->add_option_function<int>(
         "--threads", [](int n) { if (n > 0) omp_set_num_threads(n); },
         "worker threads (default: one per core); the results do not depend on it")
      ->check(number_range(1, 4096, "give 1 to 4096 threads"));
}

}  // namespace hystbench::cli
