// An effect registered the way a user's out-of-tree plugin registers one
// (HYSTBENCH_EFFECT, nothing else): `compare` computes its signature
// statistic next to the catalog's, writes and prints it, and `diagnose`
// quotes it as the candidate's evidence. Its own executable, so that the
// extra effect stays out of the catalog the other tests diagnose with.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "framework/discovery/comparison.hpp"
#include "framework/discovery/comparison_report.hpp"
#include "framework/discovery/effect_signatures.hpp"
#include "framework/discovery/evidence.hpp"
#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace {

// A rectifying term k·|v| beside gain·v; its residual signature is the
// rectified input: corr(e, |u|).
hystbench::SignatureValue rectified_correlation(const hystbench::ResidualView& r) {
  return {hystbench::correlation(r.e, r.u.cwiseAbs())};
}

class RectifiedDrive : public hystbench::Effect {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "rectified_drive";
    i.summary = "rectifying term k·|v|";
    i.citation = "a test effect";
    i.stage = hystbench::EffectStage::Nonlinearity;
    i.params = {{"k", -1.0, 1.0, 0.0, 1, -1, "", "rectified gain"}};
    i.signature = "the residual follows |u|";
    i.statistic = {"corr(e, |u|)", rectified_correlation,
                   "the residual correlates with the rectified input |u| (r = {value})"};
    return i;
  }
  bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    if (p[0] != 0.0) signal += p[0] * ctx.stage_input->cwiseAbs();
    return true;
  }
};

}  // namespace

HYSTBENCH_EFFECT(RectifiedDrive)

namespace hystbench {
namespace {

ComparisonInput rectified_case() {
  ComparisonInput in;
  in.sample_time = 0.001;
  in.t = Eigen::VectorXd::LinSpaced(3000, 0.0, 2.999);
  in.u = (2 * 3.14159265358979 * 2.0 * in.t.array()).sin().matrix();
  in.y_model = 0.5 * in.u;
  in.y = in.y_model + 0.2 * in.u.cwiseAbs();  // e = 0.2 |u|
  return in;
}

TEST(UserEffectSignature, ComputedWrittenAndPrintedWithTheCatalogs) {
  const ComparisonInput in = rectified_case();
  const Comparison m = compare_signals(in);
  const nlohmann::json s = to_json(m.signatures)["rectified_drive"];
  EXPECT_EQ(s["statistic"], "corr(e, |u|)");
  EXPECT_NEAR(s["value"].get<double>(), 1.0, 1e-9);
  EXPECT_EQ(s["sentence"], "the residual correlates with the rectified input |u| (r = 1)");
  EXPECT_TRUE(signature_in(m.signatures, "offset"));  // the catalog's are still there

  const std::string report = comparison_markdown(in, m, "t", "m", false, "");
  EXPECT_NE(report.find("| `rectified_drive` | corr(e, \\|u\\|) | 1 |"), std::string::npos)
      << report;
}

TEST(UserEffectSignature, CitedInTheEvidenceForTheCandidate) {
  const Comparison where = compare_signals(rectified_case());
  FitErrors before, after;
  before.rmse_estimation = 0.13;
  after.rmse_estimation = 0.01;
  const std::string evidence =
      evidence_sentence(EffectRegistry::instance().find("rectified_drive", "effect"),
                        signature_in(where.signatures, "rectified_drive"), before, after, -120,
                        true, "");
  EXPECT_NE(evidence.find("It helps because the residual follows |u|; here the residual "
                          "correlates with the rectified input |u| (r = 1)."),
            std::string::npos)
      << evidence;
}

}  // namespace
}  // namespace hystbench
