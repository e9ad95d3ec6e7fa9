#pragma once
// Writing a discovery ladder out: ladder.json, ladder.md, the figure of the
// error falling step by step next to the noise floor, and each step's
// diagnosis in step_K/.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/discovery/data_source.hpp"
#include "framework/discovery/ladder.hpp"

namespace hystbench {

struct LadderContext {
  const ModelData& data;
  const DataSource& source;
  const HoldoutSpec& holdout;
  std::optional<double> true_noise_sd;  // from DATA.truth.json, when known
  nlohmann::json options;
};

nlohmann::json ladder_json(const Ladder& ladder, const LadderContext& ctx);
std::string ladder_markdown(const Ladder& ladder, const LadderContext& ctx);

// Writes the ladder so far into `dir`: the step folders from `first_step`
// on (never those restored from a checkpoint), fit.json of the last rung,
// checkpoint.json, ladder.json, ladder.md and the figure. Called after every
// diagnosis with the new step only, so a stopped run leaves every finished
// step behind. Returns the files; sets `note` when figures could not be
// rendered.
std::vector<std::filesystem::path> write_ladder(const std::filesystem::path& dir,
                                                const Ladder& ladder, const LadderContext& ctx,
                                                std::string& note, std::size_t first_step = 0);

// What a resumed run must match: data, hold-out and options.
nlohmann::json checkpoint_context(const LadderContext& ctx);
// The part of it that the first rung depends on: everything but the
// ladder's own options (max_steps, refit_restarts). `hystbench diagnose
// --model` writes its diagnosis as a one-rung checkpoint under this context,
// and `discover --diagnosis` starts from it instead of diagnosing the start
// model again.
nlohmann::json first_step_context(const LadderContext& ctx);
// The options of a ladder's context that its first rung depends on.
nlohmann::json first_step_options(const Model& start, const DiagnoseOptions& o, int substeps);
// Writes `d`, the diagnosis of the fitted start model, as DIR/checkpoint.json:
// a ladder of one rung under first_step_context(ctx).
std::filesystem::path write_first_step(const std::filesystem::path& dir, const Diagnosis& d,
                                       const LadderContext& ctx);

}  // namespace hystbench
