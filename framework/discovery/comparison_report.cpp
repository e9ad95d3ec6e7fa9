#include "framework/discovery/comparison_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "framework/discovery/comparison_figures.hpp"
#include "framework/discovery/noise_floor.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/figures.hpp"

namespace hystbench {
namespace fs = std::filesystem;
namespace {

using nlohmann::json;

// Verdict thresholds on RMSE / σ.
constexpr double kAtNoiseFloor = 1.1;
constexpr double kNearNoiseFloor = 2.0;
constexpr std::size_t kWorstSegments = 10;
// r_uu(1) above this: the input is too smooth for the CCF peak lag to mean a delay.
constexpr double kSmoothInput = 0.9;

std::string num(const json& j) {
  if (j.is_number_integer()) return std::to_string(j.get<long long>());
  if (!j.is_number()) return "–";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", j.get<double>());
  return buf;
}

std::string num(double x) { return num(std::isfinite(x) ? json(x) : json()); }

std::string cell(std::string s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out.empty() ? " " : out;
}

std::string unit(const std::string& u) { return u.empty() ? "" : " [" + u + "]"; }
// "1.2 µm" in running text.
std::string with_unit(const std::string& number, const std::string& u) {
  return u.empty() ? number : number + " " + u;
}

std::string p_text(const json& p) {
  return p.is_number() && p.get<double>() < 1e-4 ? "< 0.0001" : num(p);
}

double value(const json& j) { return j.is_number() ? j.get<double>() : std::nan(""); }

std::string row(const std::vector<std::string>& cells) {
  std::string out = "|";
  for (const auto& c : cells) out += " " + c + " |";
  return out + "\n";
}

// First column left-aligned, the others right-aligned (numbers), except
// the last when `text_last` (a column of words).
std::string header_row(const std::vector<std::string>& cells, bool text_last = false) {
  std::string rule = "|";
  for (std::size_t k = 0; k < cells.size(); ++k)
    rule += k == 0 || (text_last && k + 1 == cells.size()) ? " :-- |" : " --: |";
  return row(cells) + rule + "\n";
}

std::string ratio_to_sigma(const json& rmse, const json& metrics) {
  const double sigma = value(metrics["noise_floor"]["sigma"]);
  return sigma > 0 ? num(value(rmse) / sigma) : "–";
}

// ---- sections ------------------------------------------------------------------

std::string headline(const ComparisonInput& in, const json& m) {
  const std::string yu = unit(in.y_unit);
  std::string out =
      "## Headline\n\n" + header_row({"part", "samples", "RMSE" + yu, "fit %", "relative error",
                                      "max \\|error\\|" + yu, "mean error" + yu, "RMSE / noise σ"});
  for (const char* part : {"estimation", "heldout", "all"}) {
    if (!m.contains(part)) continue;
    const json& p = m[part];
    out += row({std::string(part) == "heldout" ? "held out" : part, num(p["n"]), num(p["rmse"]),
                num(p["fit_percent"]), num(p["relative_error"]), num(p["max_abs_error"]),
                num(p["mean_error"]), ratio_to_sigma(p["rmse"], m)});
  }
  out +=
      "\nfit % = 100 (1 − ‖y − ŷ‖ / ‖y − ȳ‖); relative error = ‖y − ŷ‖ / ‖y‖. "
      "Errors in units of y" +
      (in.y_unit.empty() ? std::string() : " (" + in.y_unit + ")") +
      ". The model output ŷ is taken as given (normally simulated over the whole record).\n";
  if (!m.contains("heldout"))
    out += "No samples were held out: every number is on estimation data.\n";
  return out + "\n";
}

std::string noise_floor(const ComparisonInput& in, const json& m) {
  const json& f = m["noise_floor"];
  std::string method = f["method"];
  std::string how;
  if (method == "periodic")
    how = "from repeated periods of the excitation, σ = RMS(y_p − y_{p+1})/√2 over " +
          num(f["pairs"]) + " sample pairs" +
          (value(f["period"]) > 0 ? " (period " + num(f["period"]) + " samples)"
                                  : std::string(" (repeated segments)"));
  else if (method == "difference_mad")
    how =
        "from high-order differences of y (no repeated periods found): robust (MAD) estimate, "
        "lowest over orders 2–6 (order " +
        num(f["order"]) + ")";
  else
    how = "not estimated (fewer than " + std::to_string(kNoiseFloorFewestSamples) + " samples)";
  std::string out =
      "## Noise floor\n\nσ = " + with_unit(num(f["sigma"]), in.y_unit) + ", " + how + ".\n\n";
  const double r = value(f["rmse_over_sigma"]);
  if (!std::isfinite(r))
    out += "RMSE / σ is undefined.\n";
  else if (r <= kAtNoiseFloor)
    out += "RMSE / σ = " + num(r) +
           ": the model error is at the noise floor; nothing systematic is left to find.\n";
  else if (r <= kNearNoiseFloor)
    out += "RMSE / σ = " + num(r) +
           ": the model error is close to the noise floor; little is left to find.\n";
  else
    out += "RMSE / σ = " + num(r) +
           ": the model error is well above the noise floor; a systematic error remains.\n";
  return out + "\n";
}

// r_ue at lag τ; 0 outside the lags computed.
double ccf_at(const json& ccf, int tau) {
  for (std::size_t i = 0; i < ccf["lags"].size(); ++i)
    if (ccf["lags"][i] == tau) return value(ccf["values"][i]);
  return 0.0;
}

// A peak that falls below half its height within three lags on either
// side: a delay rather than a broad dynamic response.
bool single_peak(const json& ccf, int lag) {
  const double peak = std::abs(ccf_at(ccf, lag));
  return std::abs(ccf_at(ccf, lag - 3)) < 0.5 * peak &&
         std::abs(ccf_at(ccf, lag + 3)) < 0.5 * peak;
}

std::string correlation_verdict(const json& m, double ts) {
  const json& r = m["residual"];
  const json& lb = r["ljung_box"];
  std::string out =
      "## Residual tests\n\nComputed on the residual e = y − ŷ of the whole record "
      "(estimation and held-out samples together), N = " +
      num(m["n"]) + ".\n\n";
  const int acf_out = r["acf"]["outside"];
  if (r["white"].get<bool>())
    out += "- **Whiteness**: the residual is white (Ljung–Box Q = " + num(lb["q"]) + " over " +
           num(lb["lags"]) + " lags, p = " + p_text(lb["p_value"]) + " > 0.01); " +
           std::to_string(acf_out) + " of " + std::to_string(r["acf"]["lags"].size()) +
           " autocorrelation lags lie outside the 99 % band ±" + num(r["acf"]["bound"]) + ".\n";
  else
    out += "- **Whiteness**: the residual is **not white** (Ljung–Box Q = " + num(lb["q"]) +
           " over " + num(lb["lags"]) + " lags, p " + p_text(lb["p_value"]) +
           " ≤ 0.01): it still has structure "
           "in time; " +
           std::to_string(acf_out) + " of " + std::to_string(r["acf"]["lags"].size()) +
           " autocorrelation lags lie outside the 99 % band ±" + num(r["acf"]["bound"]) + ".\n";
  const json& c = m["residual"]["ccf"];
  const int outside = c["outside"], lag = c["peak_lag"];
  const double peak = ccf_at(c, lag);
  out += "- **Input–residual cross-correlation**: " + std::to_string(outside) + " of " +
         std::to_string(c["lags"].size()) + " lags lie outside the 99 % band ±" + num(c["bound"]) +
         " (about " + num(0.01 * double(c["lags"].size())) +
         " expected by chance); the largest is r = " + num(peak) +
         " at τ = " + std::to_string(lag) + ". ";
  const double smooth = value(c["input_lag1_autocorrelation"]);
  const bool narrow_band = smooth > kSmoothInput;
  if (outside <= 1)
    out += "The residual is independent of the input within the band.\n";
  else if (narrow_band)
    out += "The residual depends on the input, but the input is smooth (r_uu(1) = " + num(smooth) +
           "), so the correlation spreads over many lags and the lag of its peak is no delay "
           "estimate.\n";
  else if (lag > 0 && single_peak(c, lag))
    out += "The residual follows the input " + std::to_string(lag) +
           " samples earlier, with one "
           "sharp peak: a time delay of about " +
           num(lag * ts) + " s is missing.\n";
  else if (lag > 0)
    out += "The residual depends on past input: unmodelled dynamics (rate dependence).\n";
  else if (lag == 0)
    out +=
        "The residual follows the present input: the static part (gain, asymmetry, saturation) is "
        "off.\n";
  else
    out +=
        "The residual correlates most with future input: feedback in the data, or a model that "
        "reacts too early.\n";
  return out + "\n";
}

std::string segment_table(const ComparisonInput& in, const json& m) {
  std::vector<json> segs(m["by_segment"].begin(), m["by_segment"].end());
  if (segs.empty()) return "";
  std::stable_sort(segs.begin(), segs.end(), [](const json& a, const json& b) {
    return value(a["rmse"]) > value(b["rmse"]) ||
           (std::isnan(value(b["rmse"])) && !std::isnan(value(a["rmse"])));
  });
  const std::size_t shown = std::min(segs.size(), kWorstSegments);
  const std::string yu = unit(in.y_unit);
  std::string out = "### Segments, worst first" +
                    (shown < segs.size()
                         ? " (" + std::to_string(shown) + " of " + std::to_string(segs.size()) + ")"
                         : std::string()) +
                    "\n\n" +
                    header_row({"segment", "part", "samples", "RMSE" + yu, "fit %",
                                "max \\|error\\|" + yu, "RMSE / σ"});
  for (std::size_t k = 0; k < shown; ++k) {
    const json& s = segs[k];
    out +=
        row({cell(s["segment"]), s["part"] == "heldout" ? "held out" : s["part"].get<std::string>(),
             num(s["n"]), num(s["rmse"]), num(s["fit_percent"]), num(s["max_abs_error"]),
             ratio_to_sigma(s["rmse"], m)});
  }
  return out + "\n";
}

std::string amplitude_table(const ComparisonInput& in, const json& m) {
  const double total = value(m["all"]["sse"]);
  const std::string uu = unit(in.u_unit), yu = unit(in.y_unit);
  std::string out = "### Input amplitude |u − mean u| (mean u = " +
                    with_unit(num(m["amplitude_binning"]["u_mean"]), in.u_unit) +
                    "; equal-width bins)\n\n" +
                    header_row({"bin", "\\|u − mean u\\|" + uu, "samples", "RMSE" + yu,
                                "share of samples", "share of SSE"});
  const double n = value(m["n"]);
  for (const json& b : m["by_amplitude"])
    out +=
        row({num(b["bin"]), num(b["u_low"]) + " – " + num(b["u_high"]), num(b["n"]), num(b["rmse"]),
             num(value(b["n"]) / n), total > 0 ? num(value(b["sse"]) / total) : "–"});
  return out + "\n";
}

std::string branch_table(const ComparisonInput& in, const json& m) {
  const std::string yu = unit(in.y_unit);
  std::string out =
      "### Branch (loading Δu > 0, unloading Δu < 0, holding |Δu| ≤ " +
      with_unit(num(m["branch_tolerance"]), in.u_unit) + ")\n\n" +
      header_row({"branch", "samples", "RMSE" + yu, "mean error" + yu, "max \\|error\\|" + yu});
  for (const char* b : {"loading", "unloading", "holding"}) {
    const json& g = m["by_branch"][b];
    out += row({b, num(g["n"]), num(g["rmse"]), num(g["mean_error"]), num(g["max_abs_error"])});
  }
  return out + "\n";
}

std::string time_table(const ComparisonInput& in, const json& m) {
  double worst = -1;
  for (const json& w : m["by_time"]) worst = std::max(worst, value(w["rmse"]));
  const std::string yu = unit(in.y_unit);
  std::string out = "### Time windows (worst in bold)\n\n" +
                    header_row({"window", "t [s]", "samples", "RMSE" + yu, "mean error" + yu});
  for (const json& w : m["by_time"]) {
    const bool bold = value(w["rmse"]) == worst;
    const std::string rmse = bold ? "**" + num(w["rmse"]) + "**" : num(w["rmse"]);
    out += row({num(w["window"]), num(w["t_start"]) + " – " + num(w["t_end"]), num(w["n"]), rmse,
                num(w["mean_error"])});
  }
  return out + "\n";
}

// Plain sentences over the breakdown tables that follow.
std::string failure_summary(const ComparisonInput& in, const json& m) {
  std::string out;
  const auto& segs = m["by_segment"];
  if (segs.size() >= 2) {
    const json* worst = nullptr;
    std::vector<double> rmse;
    for (const json& s : segs)
      if (s["rmse"].is_number()) {
        rmse.push_back(value(s["rmse"]));
        if (!worst || value(s["rmse"]) > value((*worst)["rmse"])) worst = &s;
      }
    std::sort(rmse.begin(), rmse.end());
    if (worst && !rmse.empty() && rmse[rmse.size() / 2] > 0)
      out += "- Worst segment: " + cell((*worst)["segment"]) + " (RMSE " +
             with_unit(num((*worst)["rmse"]), in.y_unit) + ", " +
             num(value((*worst)["rmse"]) / rmse[rmse.size() / 2]) + "× the median segment).\n";
  }
  const json& top = m["by_amplitude"].back();
  const double total = value(m["all"]["sse"]), n = value(m["n"]);
  if (total > 0 && n > 0)
    out += "- The largest input amplitudes (top bin) hold " + num(100 * value(top["n"]) / n) +
           " % of the samples and " + num(100 * value(top["sse"]) / total) +
           " % of the squared error.\n";
  const json& b = m["by_branch"];
  if (b["loading"]["rmse"].is_number() && b["unloading"]["rmse"].is_number())
    out += "- RMSE while loading " + with_unit(num(b["loading"]["rmse"]), in.y_unit) +
           ", while unloading " + with_unit(num(b["unloading"]["rmse"]), in.y_unit) + ".\n";
  return out.empty() ? out : out + "\n";
}

// One row per effect, as compare_signals wrote them (effect_signatures.hpp):
// every registered effect's own statistic of this residual.
std::string signature_table(const json& m) {
  const json& signatures = m["signatures"];
  if (signatures.empty()) return "";
  std::string out =
      "## Residual signatures\n\nEvery registered effect's own statistic of this residual, as "
      "declared in its effect file: how strongly the residual shows what that effect would "
      "explain. Each falls towards its no-sign value (0 for a correlation or R², about 1 for a "
      "ratio to chance) as the residual becomes white.\n\n" +
      row({"effect", "statistic", "value", "here"}) + "| :-- | :-- | --: | :-- |\n";
  for (auto it = signatures.begin(); it != signatures.end(); ++it)
    out += row({"`" + it.key() + "`", cell(it->value("statistic", "")), num((*it)["value"]),
                cell(it->value("sentence", ""))});
  return out + "\n";
}

std::string figures(bool images, const std::string& note) {
  struct Figure {
    const char* name;
    const char* caption;
  };
  constexpr Figure list[] = {
      {"fit_model_time", "Measured and model output over time, residual below"},
      {"residual", "Residual over time (held-out spans shaded, ± noise σ dotted)"},
      {"fit_model_loops", "Hysteresis loops u–y per segment, measured and model"},
      {"segment_rmse", "RMSE per segment"},
      {"correlation", "Residual autocorrelation and input–residual cross-correlation, 99 % band"},
  };
  std::string out = "## Figures\n\n";
  for (const auto& f : list) {
    const std::string name = f.name;
    if (images) out += "![" + std::string(f.caption) + "](" + name + ".png)\n\n";
    out += std::string(f.caption) + ": [svg](" + name + ".svg), [pdf](" + name +
           ".pdf), [gnuplot script](" + name + ".gp)\n\n";
  }
  if (!note.empty()) out += "_" + note + "_\n";
  return out;
}

}  // namespace

std::string comparison_markdown(const ComparisonInput& in, const json& metrics,
                                const std::string& title, const std::string& model_text,
                                bool images, const std::string& figure_note) {
  const double ts = value(metrics["sample_time"]);
  std::string out = "# " + title + "\n\nModel: `" +
                    (model_text.empty() ? std::string("(not named)") : model_text) + "`. " +
                    num(metrics["n"]) + " samples, sample time " + num(ts) + " s" +
                    (in.u_unit.empty() ? std::string() : ", input in " + in.u_unit) +
                    (in.y_unit.empty() ? std::string() : ", output in " + in.y_unit) +
                    ". All numbers are in metrics.json.\n\n";
  out += headline(in, metrics) + noise_floor(in, metrics) + correlation_verdict(metrics, ts);
  out += "## Where the model fails\n\n" + failure_summary(in, metrics) +
         segment_table(in, metrics) + amplitude_table(in, metrics) + branch_table(in, metrics) +
         time_table(in, metrics);
  return out + signature_table(metrics) + figures(images, figure_note);
}

std::vector<fs::path> write_comparison(const fs::path& dir, const ComparisonInput& in,
                                       const json& metrics, const std::string& title,
                                       const std::string& model_text) {
  fs::create_directories(dir);
  std::vector<fs::path> written;
  write_file_atomic(dir / "metrics.json", metrics.dump(2) + "\n");
  written.push_back(dir / "metrics.json");
  const FigureFiles fig = write_comparison_figures(dir, in, metrics, title);
  written.insert(written.end(), fig.data.begin(), fig.data.end());
  written.insert(written.end(), fig.scripts.begin(), fig.scripts.end());
  std::string note;
  const auto images = render_figures(dir, fig.scripts, note);
  written.insert(written.end(), images.begin(), images.end());
  const bool have_png = std::any_of(images.begin(), images.end(),
                                    [](const fs::path& p) { return p.extension() == ".png"; });
  write_file_atomic(dir / "report.md",
                    comparison_markdown(in, metrics, title, model_text, have_png, note));
  written.push_back(dir / "report.md");
  return written;
}

}  // namespace hystbench
