#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/output_folder.hpp"
#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/effect_source.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/proposal_report.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/json_file.hpp"
#include "framework/report/provenance.hpp"
#include "framework/svr/svr_model.hpp"

namespace hystbench::cli {
namespace {

struct ProposeCommandOptions {
  DataOptions data;
  OutputOptions output;
  std::string from_fit, name = "proposed_term";
  ProposeOptions propose;
};

void check_options(const ProposeCommandOptions& o) {
  if (o.propose.degree < 1 || o.propose.degree > 6)
    throw InputError("--degree " + std::to_string(o.propose.degree) + ": give 1 to 6");
  if (o.propose.regression.max_terms < 1)
    throw InputError("--max-terms " + std::to_string(o.propose.regression.max_terms) + ": give at least 1");
  check_effect_name(o.name);
}

void print_proposal(const Proposal& p, const std::string& unit) {
  std::cout << "residual RMSE " << p.rmse_estimation << " -> " << p.rmse_estimation_after;
  if (p.n_heldout > 0) std::cout << ", held out " << p.rmse_heldout << " -> " << p.rmse_heldout_after;
  std::cout << (unit.empty() ? "" : " " + unit) << " (" << p.library_size << " candidate terms)\n";
  if (p.terms.empty()) std::cout << "no term explains enough of the residual to be proposed\n";
  for (std::size_t i = 0; i < p.terms.size(); ++i) {
    const ProposedTerm& t = p.terms[i];
    std::cout << "  " << i + 1 << ". " << term_stage_name(t.term.stage) << ": " << t.term.text() << "  coefficient "
              << t.coefficient << " ± " << t.standard_error << "  share " << 100.0 * t.err << " %\n";
  }
}

// The fitted model's effects with `name` added, or in place of msd when
// the generated effect extends it.
std::string model_with(const Model& model, const std::string& name, bool replaces_msd) {
  std::vector<std::string> effects = model.effects();
  if (replaces_msd)
    std::replace(effects.begin(), effects.end(), std::string("msd"), name);
  else
    effects.push_back(name);
  return join(effects, ",");
}

// The first term as an effect plugin in DIR/effect, when it can be written.
GeneratedEffect write_effect(const Proposal& p, const ProposeCommandOptions& o, const DataSource& source,
                             const FitRecord& fit, const std::filesystem::path& dir) {
  if (p.terms.empty()) return {};
  const Model& model = fit.model;
  try {
    const std::string text =
        proposed_effect_source(p.terms[0], {o.name, source.file_name(), model.text(), fit.x[0]});
    create_output_folder(dir / "effect");
    write_file_atomic(dir / "effect" / (o.name + ".cpp"), text);
    write_file_atomic(dir / "effect" / "CMakeLists.txt", proposed_effect_cmake(o.name));
    return {o.name, model_with(model, o.name, p.terms[0].term.stage == TermStage::Dynamics), ""};
  } catch (const InputError& e) {
    return {"", "", e.what()};
  }
}

nlohmann::json effect_json(const GeneratedEffect& e) {
  if (!e.not_written.empty()) return {{"not_written", e.not_written}};
  if (e.name.empty()) return nullptr;
  return {{"source", "effect/" + e.name + ".cpp"}, {"model", e.model}};
}

// The fit file --fit names: the file itself, or in a discover folder the
// rung its ladder.json says propose extends (sound_rung.hpp), said on stdout.
std::string fit_file(const std::string& given) {
  if (!std::filesystem::is_directory(given)) return given;
  const auto dir = std::filesystem::path(given);
  if (!std::filesystem::exists(dir / "ladder.json"))
    throw InputError("--fit " + given + ": a folder without ladder.json; give a fit.json, or a discover folder");
  const nlohmann::json ladder = read_json_file((dir / "ladder.json").string(), "ladder file");
  const nlohmann::json from = ladder.value("propose_from", nlohmann::json());
  if (!from.is_object()) return (dir / "fit.json").string();  // written before the rung was chosen
  std::cout << from.value("sentence", "") << "\n";
  return (dir / from.value("fit", "fit.json")).string();
}

void run_propose(const ProposeCommandOptions& o, bool holdout_given) {
  check_options(o);
  const std::string from_fit = fit_file(o.from_fit);
  const nlohmann::json file = read_json_file(from_fit, "fit file");
  if (SvrHammerstein::is_model_file(file))
    throw InputError("--fit " + from_fit + ": an SVR model has no chain for a term to enter; propose extends a "
                     "catalog model's fit.json (hystbench fit, diagnose or discover)");
  const FitRecord fit = FitRecord::read(from_fit);
  DataSource source = o.data.source();
  // The fit's own hold-out on its own data, so that the held-out check
  // judges on samples the fit never saw.
  const ModelData data = data_for_fit(o.data, fit, source, holdout_given, HoldoutSpec::Mode::Auto);
  const auto dir = o.output.prepare("proposals.json");

  StatusLine status;
  status.show("propose: regressing the residual of " + fit.model.text() + " on the term library (" +
              std::to_string(data.size()) + " samples)");
  const Proposal p = propose_terms(fit.model, fit.x, data, o.propose);
  status.finish();
  const GeneratedEffect effect = write_effect(p, o, source, fit, dir);
  nlohmann::json out = p.to_json();
  out["data"] = source.to_json();
  out["fit"] = from_fit;
  out["effect"] = effect_json(effect);
  out["provenance"] = provenance(1, 0);
  write_file_atomic(dir / "proposals.json", out.dump(2) + "\n");
  write_file_atomic(dir / "proposals.md", proposal_markdown(p, source.file_name(), source.y_unit, effect));
  print_proposal(p, source.y_unit);
  if (p.falls_short) std::cout << beyond_library(p) << "\n";
  if (!effect.not_written.empty()) std::cout << "no effect written: " << effect.not_written << "\n";
  std::cout << "wrote " << (dir / "proposals.md").string() << " and proposals.json"
            << (effect.name.empty() ? "" : ", and effect/" + effect.name + ".cpp (fit it as --model " + effect.model + ")")
            << "\n";
}

}  // namespace

Action add_propose_command(CLI::App& app) {
  auto o = std::make_shared<ProposeCommandOptions>();
  auto* cmd = app.add_subcommand(
      "propose", "Propose the term a fitted model lacks when no catalog effect explains its residual: sparse "
                 "(orthogonal forward) regression of the residual on powers, play operators and products of the "
                 "model's own signals, each entering where its signal lives; writes proposals.json, proposals.md and the first term as an effect "
                 "plugin (effect/NAME.cpp)");
  add_data_options(cmd, o->data);
  cmd->add_option("--fit", o->from_fit, "fit.json of the model to extend (hystbench fit, diagnose or discover), or a discover folder: "
                  "then the last rung whose added effects the data support")
      ->required();
  cmd->add_option("--degree", o->propose.degree, "largest total degree of a term (1-6)")->capture_default_str();
  cmd->add_option("--max-terms", o->propose.regression.max_terms, "terms proposed at most")->capture_default_str();
  cmd->add_option("--name", o->name, "name of the generated effect")->capture_default_str();
  add_output_options(cmd, o->output);
  add_quiet_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, cmd, load_plugins] {
    load_plugins();
    run_propose(*o, cmd->count("--holdout") > 0);
  };
}

}  // namespace hystbench::cli
