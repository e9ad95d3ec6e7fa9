#include "framework/control/model_stream.hpp"

#include "framework/control/scaled_stream.hpp"
#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/io/data_path.hpp"
#include "framework/io/json_file.hpp"
#include "framework/model/streaming_model.hpp"

namespace hystbench {
namespace {

ResolvedModel from_fit(const nlohmann::json& spec, const std::filesystem::path& base_dir,
                       const std::string& where) {
  if (!spec["fit"].is_string()) throw InputError(where + ".fit: give the path of a fit.json");
  const auto path = resolve_data_path(spec["fit"].get<std::string>(), base_dir, where + ".fit");
  FitRecord record = FitRecord::read(path);
  // "seed_chain/fit.json": fit files are told apart by their folder.
  const auto name = path.parent_path().filename() / path.filename();
  return {record.model, record.x, record.scales, name.string() + ": " + record.model.text(), InputHold::Linear};
}

ResolvedModel from_effects(const nlohmann::json& spec, const std::filesystem::path& base_dir,
                           const std::string& where) {
  if (!spec["model"].is_string())
    throw InputError(where + ".model: give the effects as a string, e.g. \"hysteresis,asymmetry\"");
  Model model = Model::parse(spec["model"].get<std::string>(), where + ".model");
  SignalScales scales;
  if (spec.contains("scales")) scales = SignalScales::from_json(spec["scales"], where + ".scales");
  nlohmann::json values = spec.value("parameters", nlohmann::json());
  // A file of values, as `hystbench simulate --params` reads it.
  if (values.is_string())
    values = read_json_file(resolve_data_path(values.get<std::string>(), base_dir, where + ".parameters"),
                            "parameter file");
  if (!values.is_object())
    throw InputError(where + ".parameters: give the physical value of every parameter of " +
                     model.text() + " as an object {\"gain\": .., ...} or the name of a JSON file holding one");
  const Eigen::VectorXd x = model.from_physical(values, scales, where + ".parameters");
  return {model, x, scales, model.text(), InputHold::Linear};
}

}  // namespace

const std::vector<std::string>& model_stream_keys() {
  static const std::vector<std::string> keys = {"fit", "model", "parameters", "scales",
                                                "input_hold"};
  return keys;
}

ResolvedModel resolve_model(const nlohmann::json& spec, const std::filesystem::path& base_dir,
                            const std::string& where) {
  if (!spec.is_object() || spec.contains("fit") == spec.contains("model"))
    throw InputError(where + ": give either \"fit\": \"fit.json\" or \"model\" with "
                             "\"parameters\"");
  ResolvedModel r = spec.contains("fit") ? from_fit(spec, base_dir, where) : from_effects(spec, base_dir, where);
  r.hold = parse_input_hold(optional_text(spec, "input_hold", "linear", where), where + ".input_hold");
  return r;
}

std::unique_ptr<StreamingModel> streaming_model(const ResolvedModel& r, double sample_time,
                                                const std::string& where) {
  auto stream = std::make_unique<StreamingModel>(r.model, r.x, sample_time, r.hold, where);
  if (!stream->valid())
    throw InputError(where + ": the parameters of " + r.model.text() +
                     " are invalid (the model cannot be simulated); check their values");
  return stream;
}

ModelStream model_stream(const nlohmann::json& spec, const std::filesystem::path& base_dir,
                         double sample_time, const std::string& where) {
  const ResolvedModel r = resolve_model(spec, base_dir, where);
  return {std::make_unique<ScaledStream>(streaming_model(r, sample_time, where), 1.0 / r.scales.u, r.scales.y),
          r.description};
}

}  // namespace hystbench
