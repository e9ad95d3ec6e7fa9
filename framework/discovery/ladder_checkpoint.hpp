#pragma once
// checkpoint.json of a discovery run: after every diagnosis the ladder so
// far, enough to continue it exactly as the uninterrupted run would
// (`hystbench discover --resume`). Parameters are stored in normalised
// units with every digit, so a resumed run starts bit for bit where the
// stopped one was; everything that can be recomputed from (model,
// parameters, data) is recomputed instead of stored.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "framework/discovery/ladder.hpp"

namespace hystbench {

// {"format", "context", "steps", "diagnoses", "stopped_by_limit"}; `context`
// holds what a resumed run must match (data, hold-out, options).
nlohmann::json checkpoint_json(const Ladder& ladder, const nlohmann::json& context);

// Reads DIR/checkpoint.json and rebuilds the ladder on `data`. Throws
// InputError when the file is missing or unreadable, or when its context
// differs from `context`, naming the first key that differs. `option` is the
// command-line option that named DIR: "--resume" (a stopped discover run) or
// "--diagnosis" (a diagnose run of the start model); the messages say how
// to make the file that fits.
Ladder read_checkpoint(const std::filesystem::path& dir, const nlohmann::json& context,
                       const ModelData& data, const DiscoverOptions& options,
                       const std::string& option = "--resume");

}  // namespace hystbench
