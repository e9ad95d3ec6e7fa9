#pragma once
// Where a result came from: enough to reproduce it or to tell why it differs.
#include <cstdint>
#include <nlohmann/json.hpp>

namespace hystbench {

// version, git commit, compiler and flags, OpenMP threads, seed, UTC date,
// host, and "plugins" (path as given and names registered) when any were
// loaded.
nlohmann::json provenance(int threads, std::uint64_t seed);

}  // namespace hystbench
