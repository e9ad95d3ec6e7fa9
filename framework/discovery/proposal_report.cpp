#include "framework/discovery/proposal_report.hpp"

#include "framework/core/text.hpp"
#include "framework/report/markdown.hpp"

namespace hystbench {
namespace {

using markdown::num;

std::string percent(double share) { return format_number("%.3g", 100.0 * share) + " %"; }

std::string terms_table(const Proposal& p, const std::string& unit) {
  std::string out = markdown::header_row({"rank", "stage", "term", "enters at", "coefficient ± se",
                                          "share of residual", "ΔBIC", "held-out RMSE after" + unit,
                                          "runner-up (share)"},
                                         "rllllrrrl");
  for (std::size_t i = 0; i < p.terms.size(); ++i) {
    const ProposedTerm& t = p.terms[i];
    const std::string runner = t.runner_up.empty() ? "–" : t.runner_up + " (" + percent(t.runner_up_err) + ")";
    out += markdown::row({std::to_string(i + 1), term_stage_name(t.term.stage), t.term.text(),
                          entry_name(t.term.entry()),
                          num(t.coefficient) + " ± " + num(t.standard_error), percent(t.err), num(t.delta_bic),
                          num(t.heldout_rmse), runner});
  }
  return out;
}

std::string refused_text(const Proposal& p) {
  if (p.refused.empty()) return "Every candidate was taken or none was left.\n";
  const std::string why = p.refused_by == "bic"       ? "it lowers the BIC by less than 10"
                          : p.refused_by == "heldout" ? "it lowers the held-out residual by less than " +
                                                            format_number("%.3g", 100.0 * p.options.regression.heldout_gain) + " %"
                                                      : "the proposal already has --max-terms terms";
  return "The choice stopped at " + p.refused + " (" + percent(p.refused_err) + " of the residual): " + why + ".\n";
}

std::string next_steps(const GeneratedEffect& e) {
  if (!e.not_written.empty()) return "\n## The first term as an effect\n\nNo effect was written: " + e.not_written + ".\n";
  if (e.name.empty()) return "";
  return "\n## The first term as an effect\n\n"
         "`effect/" + e.name + ".cpp` is the first term as an effect plugin, its coefficient `c` "
         "free between ten times the proposed value either way. Build it, then fit the model with it, "
         "or let discover refit it with the rest of the model (docs/plugins.md, \"Out of the tree: a "
         "shared library\"; an installed hystbench takes -DCMAKE_PREFIX_PATH=PREFIX instead):\n\n"
         "```sh\n"
         "cmake -S effect -B effect/build -Dhystbench_DIR=HYSTBENCH_BUILD_TREE\n"
         "cmake --build effect/build\n"
         "hystbench fit --data DATA --model " + e.model + " --plugin effect/build/" + e.name + ".so --out fit\n"
         "hystbench discover --data DATA --start " + e.model + " --plugin effect/build/" + e.name + ".so --out discovery\n"
         "```\n";
}

}  // namespace

std::string proposal_markdown(const Proposal& p, const std::string& data_name, const std::string& y_unit,
                              const GeneratedEffect& effect) {
  const std::string unit = y_unit.empty() ? "" : " (" + y_unit + ")";
  std::string out = "# Proposed terms: " + p.model + " on " + data_name + "\n\n";
  out += "What the fitted model leaves, regressed on " + std::to_string(p.library_size) +
         " candidate terms built from its own signals (degree ≤ " + std::to_string(p.options.degree) +
         "), each entering where its signal lives; the model's own parameters are refitted with them "
         "(method: docs/discovery.md, \"Proposing a missing term\").\n\n";
  out += "Residual RMSE" + unit + ": estimation " + num(p.rmse_estimation) + " → " + num(p.rmse_estimation_after) +
         " (" + std::to_string(p.n_estimation) + " samples)";
  if (p.n_heldout > 0)
    out += ", held out " + num(p.rmse_heldout) + " → " + num(p.rmse_heldout_after) + " (" +
           std::to_string(p.n_heldout) + " samples)";
  out += ", linearised about the fit.\n\n";
  if (p.terms.empty())
    out += "**No term is proposed**: none explains enough of the residual.\n\n";
  else
    out += terms_table(p, unit) + "\n";
  out += refused_text(p);
  if (p.falls_short) out += "\n**Beyond the library.** " + beyond_library(p) + "\n";
  out += "\nCoefficients are in normalised units (u and y divided by the fit's scales, rates per second). "
         "A runner-up close to its term's share means the data hardly tell the two apart.\n";
  return out + next_steps(effect);
}

}  // namespace hystbench
