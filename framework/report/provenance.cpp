#include "framework/report/provenance.hpp"

#include <unistd.h>

#include <ctime>

#include "framework/core/plugin_loader.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {

#if defined(__clang__)
constexpr const char* kCompiler = "clang " __clang_version__;
#else
constexpr const char* kCompiler = "gcc " __VERSION__;
#endif

std::string host_name() {
  char buf[256] = {};
  return gethostname(buf, sizeof buf - 1) == 0 ? buf : "unknown";
}

}  // namespace

nlohmann::json provenance(int threads, std::uint64_t seed) {
  nlohmann::json j = {{"version", HYSTBENCH_VERSION},
          {"git_commit", HYSTBENCH_GIT_COMMIT},
          {"compiler", kCompiler},
          {"flags", HYSTBENCH_CXX_FLAGS},
          {"threads", threads},
          {"seed", seed},
          {"date", time_now("%Y-%m-%dT%H:%M:%SZ", true)},
          {"host", host_name()}};
  for (const auto& p : loaded_plugins())
    j["plugins"].push_back({{"path", p.path}, {"names", p.names}});
  return j;
}

}  // namespace hystbench
