#pragma once
// Beyond the catalog (docs/discovery.md#beyond-the-catalog): something
// systematic is left in a fit and no catalog effect captures it. Then a
// diagnosis says so plainly instead of adding the nearest effect: its
// completeness kind becomes "beyond_catalog", and it says where the error
// concentrates, what each catalog effect did on the held-out data, at which
// stage the best single term of the proposal library would enter, and to
// run `hystbench propose`.
//
// Partial help is not enough: a significant candidate is added only when it
// removes at least 40 % of what the current model leaves above the noise on
// the held-out data (on the estimation data when nothing is held out),
//
//   share = (RMSE_before² − RMSE_after²) / (RMSE_before² − σ²)  ≥  0.4,
//
// σ the noise estimate. The rule applies only while the fit is above the
// noise floor (completeness kind "systematic"). Where 0.4 comes from
// (benchmarks/stopping_share.sh, results/stopping_share): catalog effects
// standing in for physics the catalog lacks removed at most 30 % (a drag
// growing with speed taken as hysteresis: 28 %), every hidden catalog effect
// at least 71 %, and the additions on the measured benchmarks at least 57 %.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/proposal.hpp"

namespace hystbench {

struct Diagnosis;

constexpr double kPartialShare = 0.4;

// The share above, NaN when the model is at or below the noise (no excess).
double excess_share(double rmse_before, double rmse_after, double sigma);

struct BeyondCatalog {
  bool applies = false;
  // The significant candidate the partial-help rule refused ("" when none).
  std::string refused;
  double refused_share = 0.0;
  // Every candidate tried, with the share of the excess it removed (on `judged_on`).
  std::vector<std::pair<std::string, double>> tried;
  std::vector<std::string> where;  // sentences: where the error concentrates
  std::vector<StageLead> stages;   // the best single term of each stage
  std::string advice;
  std::string judged_on = "held-out";  // the data the shares are of: "held-out" or "estimation"

  nlohmann::json to_json() const;
  // Reads what to_json wrote (a discover checkpoint keeps it); throws
  // nlohmann::json::exception or InputError on a malformed object.
  static BeyondCatalog from_json(const nlohmann::json& j);
};

// The held-out excess share of a candidate of `d` (estimation when nothing
// is held out).
double candidate_share(const Diagnosis& d, const std::string& effect);

// Whether refitting the leading candidates could change a verdict the
// partial-help rule would otherwise refuse: false above the noise floor when
// no candidate's screened fit removes even a quarter of kPartialShare (10 %)
// of the excess. A refit restores a candidate a poor basin had hidden, but
// from under 10 % to 40 % it would have to quadruple what the candidate
// removed; in results/hidden_effects no verdict depends on such a refit, and
// on Silverbox's last rung (best share 1.5 %) it cost two minutes.
bool refit_could_pass(const Diagnosis& d);

// The "Beyond the catalog" section of report.md and ladder.md ("" when it
// does not apply); `data_name` names the measurement in the propose command,
// `fit` what it extends (a discover folder: its sound rung, sound_rung.hpp).
std::string beyond_catalog_markdown(const BeyondCatalog& b, const std::string& data_name,
                                    const std::string& fit = "DIR/fit.json");

// Fills d.beyond and turns d.completeness into "beyond_catalog" when the
// verdict is "none" and something systematic is left; otherwise nothing.
void describe_beyond_catalog(Diagnosis& d, const ModelData& data);

}  // namespace hystbench
