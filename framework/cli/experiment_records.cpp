#include "framework/cli/experiment_records.hpp"

#include <ostream>
#include <vector>

#include "framework/cli/simulation_recipe.hpp"
#include "framework/core/parameters.hpp"
#include "framework/io/data_path.hpp"
#include "framework/io/json_file.hpp"
#include "framework/model/model.hpp"

namespace hystbench::cli {
namespace fs = std::filesystem;
namespace {

struct Record {
  SimulationRecipe recipe;
  fs::path root;  // where the recipe's relative names start
};

std::string required_text(const nlohmann::json& j, const std::string& key, const std::string& where) {
  const std::string text = optional_text(j, key, "", where);
  if (text.empty()) throw InputError(where + "." + key + ": missing; give the file name as a string");
  return text;
}

SimulationRecipe read_recipe(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where + ": expected an object of `hystbench simulate` options");
  require_known_keys(j, {"out", "model", "params", "excitation", "noise", "resolution", "seed", "input_unit",
                         "output_unit", "substeps", "input_hold", "form"},
                     where);
  SimulationRecipe r;
  r.out = required_text(j, "out", where);
  r.params = required_text(j, "params", where);
  r.excitation = required_text(j, "excitation", where);
  r.model = optional_text(j, "model", "", where);
  r.form = optional_text(j, "form", r.form, where);
  if (!known_form(r.form))
    throw InputError(where + ".form = \"" + r.form + "\": give \"increment\" or \"paper\"");
  r.input_unit = optional_text(j, "input_unit", "", where);
  r.output_unit = optional_text(j, "output_unit", "", where);
  r.input_hold = parse_input_hold(optional_text(j, "input_hold", "spline", where), where + ".input_hold");
  r.noise = optional_number(j, "noise", r.noise, 0.0, kMaxRecipeNoise, where);
  r.resolution = optional_number(j, "resolution", 0.0, 0.0, kMaxRecipeResolution, where);
  r.substeps = static_cast<int>(optional_number(j, "substeps", 0, 0, kMaxRecipeSubsteps, where));
  const double seed = optional_number(j, "seed", 1, 0, 9007199254740992.0, where);
  if (seed != static_cast<double>(static_cast<std::uint64_t>(seed)))
    throw InputError(where + ".seed: give a whole number of 0 or more");
  r.seed = static_cast<std::uint64_t>(seed);
  if (!r.model.empty()) Model::parse(r.model);  // names an unknown effect now, before anything is written
  return r;
}

// The folder the recipe's names start from: where its parameter file is
// found, looked up as the experiment's own files are.
fs::path root_of(const SimulationRecipe& r, const fs::path& base_dir, const std::string& where) {
  fs::path root = resolve_data_path(r.params, base_dir, where + ".params");
  const fs::path name(r.params);
  for (auto part = name.begin(); part != name.end(); ++part) root = root.parent_path();
  resolve_data_path((root / r.excitation).string(), {}, where + ".excitation");
  return root;
}

bool exists_for(const std::string& name, const fs::path& base_dir) {
  try {
    resolve_data_path(name, base_dir, "");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

std::string make_missing_records(const fs::path& experiment, std::ostream& log) {
  const nlohmann::json x = read_json_file(experiment, "experiment file");
  if (!x.is_object() || !x.contains("records")) return "";
  const std::string where = experiment.string() + ".records";
  if (!x["records"].is_string()) throw InputError(where + ": give the name of a records file as a string");
  const fs::path base_dir = experiment.parent_path();
  const fs::path file = resolve_data_path(x["records"].get<std::string>(), base_dir, where);
  const nlohmann::json j = read_json_file(file, "records file");
  const std::string at = file.string();
  if (!j.is_object()) throw InputError(at + ": expected an object with \"simulate\" and \"made_by\"");
  require_known_keys(j, {"description", "made_by", "simulate"}, at);
  const std::string made_by = optional_text(j, "made_by", "", at);
  const nlohmann::json list = j.value("simulate", nlohmann::json::array());
  if (!list.is_array()) throw InputError(at + ".simulate: expected an array of `hystbench simulate` options");
  std::vector<Record> missing;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string w = at + ".simulate[" + std::to_string(i) + "]";
    Record r{read_recipe(list[i], w), {}};
    r.root = root_of(r.recipe, base_dir, w);
    if (!exists_for(r.recipe.out, base_dir)) missing.push_back(std::move(r));
  }
  for (const Record& r : missing) {
    fs::create_directories((r.root / r.recipe.out).parent_path());
    const SimulatedRecord s = write_simulated_record(r.recipe, r.root);
    log << "made the missing record " << (r.root / r.recipe.out).string() << " (" << s.samples
        << " samples) as `" << simulate_command_line(r.recipe) << "` does\n";
  }
  return made_by;
}

}  // namespace hystbench::cli
