#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "framework/cli/commands.hpp"
#include "framework/cli/fit_summary.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/core/error.hpp"
#include "framework/discovery/ladder_checkpoint.hpp"
#include "framework/discovery/ladder_report.hpp"
#include "framework/discovery/separability.hpp"
#include "framework/discovery/sound_rung.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/io/truth_file.hpp"

namespace hystbench::cli {
namespace {

struct DiscoverCommandOptions {
  DataOptions data;
  FitCliOptions fit;
  DiagnoseCliOptions diagnose;
  OutputOptions output;
  std::string start = "none";
  int max_steps = 8, refit_restarts = 1;
  bool resume = false;
  std::string diagnosis;  // a diagnose folder of the start model: its first rung
};

// The diagnose run's report, figures and diagnosis.json become step 0's, as
// discover would have written them itself.
void copy_first_step(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::filesystem::create_directories(to);
  for (const auto& entry : std::filesystem::directory_iterator(from))
    if (entry.is_regular_file() && entry.path().filename() != "checkpoint.json")
      std::filesystem::copy_file(entry.path(), to / entry.path().filename(),
                                 std::filesystem::copy_options::overwrite_existing);
}

std::optional<double> true_noise_sd(const std::string& data_path) {
  const auto truth = read_truth(data_path);
  const auto noise = truth.value("noise", nlohmann::json::object());
  if (noise.is_object() && noise.value("sd", nlohmann::json()).is_number())
    return noise["sd"].get<double>();
  return std::nullopt;
}

void print_step(const Ladder& ladder, const std::string& unit) {
  const LadderStep& s = ladder.steps.back();
  const Diagnosis& d = ladder.diagnoses.back();
  std::cout << "step " << ladder.steps.size() - 1 << (s.added.empty() ? "" : " (+" + s.added + ")")
            << ": " << s.model.text() << "  ";
  print_errors(s.errors, unit);
  std::cout << "  verdict: " << d.verdict << (d.close_call.close ? " (close call)" : "")
            << "; complete: " << (d.completeness.complete ? "yes" : "no") << std::endl;
}

// What the record cannot tell apart, and what the final effects are where
// their names would mislead.
void print_what_the_record_cannot_tell(const Ladder& ladder) {
  const ExcitationContent& e = ladder.diagnoses.back().where.excitation;
  std::cout << e.summary() << "\n";
  for (const auto& p : inseparable_pairs(ladder.final_effects(), e)) std::cout << p.sentence(e) << "\n";
  for (const auto& effect : ladder.diagnoses.back().check.effects)
    if (!effect.reading.empty()) std::cout << effect.reading << "\n";
}

void run_discover(DiscoverCommandOptions& o) {
  DataSource source = o.data.source();
  const Measurement m = source.load();
  const HoldoutSpec holdout = o.data.holdout_spec();
  Model start = Model::parse(o.start, "--start");
  start.set_substeps(o.fit.substeps);
  start.set_input_hold(o.fit.input_hold);
  const ModelData data = prepare_fit_data(m, SignalScales::of(m), holdout, start);
  DiscoverOptions options;
  options.diagnose = o.diagnose.diagnose_options(o.fit.fit_options(), source);
  options.max_steps = o.max_steps;
  options.refit_restarts = o.refit_restarts;
  options.substeps = o.fit.substeps;
  options.input_hold = o.fit.input_hold;
  nlohmann::json context_options = first_step_options(start, options.diagnose, o.fit.substeps);
  context_options["max_steps"] = o.max_steps;
  context_options["refit_restarts"] = o.refit_restarts;
  const LadderContext ctx{data, source, holdout, true_noise_sd(source.path), context_options};
  // A resumed run, or one from a diagnosis, reads its checkpoint before
  // anything is written.
  std::optional<Ladder> restored;
  if (o.resume && !o.diagnosis.empty())
    throw InputError("discover: give --resume (continue a stopped run) or --diagnosis (start from a "
                     "diagnose run), not both");
  if (o.resume) restored = read_checkpoint(o.output.out, checkpoint_context(ctx), data, options);
  if (!o.diagnosis.empty())
    restored = read_checkpoint(o.diagnosis, first_step_context(ctx), data, options, "--diagnosis");
  const auto dir = o.resume ? std::filesystem::path(o.output.out) : o.output.prepare("ladder.json");
  if (!o.diagnosis.empty()) copy_first_step(o.diagnosis, dir / "step_0");

  StatusLine status;
  std::size_t step = restored ? restored->diagnoses.size() : 0;
  options.diagnose.fit.status = [&](const std::string& s) {
    status.show("discover step " + std::to_string(step) + ": " + s);
  };
  const std::string unit = source.y_unit;
  std::string note;
  const auto on_step = [&](const Ladder& ladder) {
    status.finish();
    print_step(ladder, unit);
    write_ladder(dir, ladder, ctx, note, ladder.diagnoses.size() - 1);
    step = ladder.diagnoses.size();
  };
  if (o.resume)
    std::cout << "resuming after step " << restored->diagnoses.size() - 1 << " ("
              << restored->steps.back().model.text() << ")" << std::endl;
  if (!o.diagnosis.empty()) {
    std::cout << "from " << o.diagnosis << ", ";
    print_step(*restored, unit);
  }
  const Ladder ladder = restored ? resume_discover(std::move(*restored), data, options, on_step)
                                 : discover(start, data, options, on_step);
  status.finish();
  write_ladder(dir, ladder, ctx, note, ladder.diagnoses.size());
  std::cout << "final model: " << ladder.steps.back().model.text() << "\n"
            << "complete: " << (ladder.completeness().complete ? "yes" : "no") << ". "
            << ladder.completeness().reason << "\n";
  print_what_the_record_cannot_tell(ladder);
  if (!ladder.completeness().complete)
    std::cout << "given --fit " << dir.string() << ", " << sound_rung(ladder).sentence() << "\n";
  if (!note.empty()) std::cout << note << "\n";
  std::cout << "wrote " << (dir / "ladder.md").string() << ", ladder.json and fit.json\n";
}

}  // namespace

Action add_discover_command(CLI::App& app) {
  auto o = std::make_shared<DiscoverCommandOptions>();
  auto* cmd = app.add_subcommand(
      "discover", "From a start model, repeat diagnose -> add the missing effect -> refit until "
                  "nothing significant is missing; writes ladder.json, ladder.md, a figure of the "
                  "error falling, each step's diagnosis and the final fit.json");
  add_data_options(cmd, o->data);
  cmd->add_option("--start", o->start, "effects of the start model (\"none\": the gain alone)")
      ->capture_default_str();
  cmd->add_option("--max-steps", o->max_steps, "effects added at most")
      ->capture_default_str()->check(number_range(0, 50, "give 0 to 50 steps"));
  cmd->add_option("--refit-restarts", o->refit_restarts,
                  "global restarts of each extended model that compete with its warm refit")
      ->capture_default_str()->check(number_range(0, 100, "give 0 to 100 restarts"));
  cmd->add_flag("--resume", o->resume,
                "continue the stopped run in --out from its last finished step (checkpoint.json), "
                "with the same data and options");
  cmd->add_option("--diagnosis", o->diagnosis,
                  "start from this folder of `hystbench diagnose --model START` (same data and options) "
                  "instead of diagnosing the start model again");
  add_fit_options(cmd, o->fit);
  add_diagnose_options(cmd, o->diagnose);
  add_output_options(cmd, o->output);
  add_quiet_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    run_discover(*o);
  };
}

}  // namespace hystbench::cli
