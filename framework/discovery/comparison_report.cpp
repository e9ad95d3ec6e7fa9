#include "framework/discovery/comparison_report.hpp"

#include <algorithm>
#include <cmath>

#include "framework/discovery/comparison_figures.hpp"
#include "framework/discovery/noise_floor.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/figures.hpp"
#include "framework/report/markdown.hpp"

namespace hystbench {
namespace fs = std::filesystem;
namespace {

// Verdict thresholds on RMSE / σ.
constexpr double kAtNoiseFloor = 1.1;
constexpr double kNearNoiseFloor = 2.0;
constexpr std::size_t kWorstSegments = 10;
// r_uu(1) above this: the input is too smooth for the CCF peak lag to mean a delay.
constexpr double kSmoothInput = 0.9;

using markdown::cell;
using markdown::header_row;
using markdown::num;
using markdown::row;

// Counts (samples, lags, bins) print in full, not as %.4g.
std::string count(long long n) { return std::to_string(n); }

std::string unit(const std::string& u) { return u.empty() ? "" : " [" + u + "]"; }
// "1.2 µm" in running text.
std::string with_unit(const std::string& number, const std::string& u) {
  return u.empty() ? number : number + " " + u;
}

std::string p_text(double p) { return p < 1e-4 ? "< 0.0001" : num(p); }

std::string ratio_to_sigma(double rmse, const Comparison& m) {
  const double sigma = m.noise_floor.sigma;
  return sigma > 0 ? num(rmse / sigma) : "–";
}

// ---- sections ------------------------------------------------------------------

// Which record the numbers are on, where the headline's rows do not say it.
std::string record_sentence(const ComparisonInput& in, const Comparison& m) {
  using Record = ComparisonInput::Record;
  if (in.record == Record::Other) return "The model was fitted on another record: every number is a test score.\n";
  if (m.parts.heldout) return "";
  if (in.record == Record::Unknown)
    return "No samples were held out, and the model file does not name the record it was fitted on: these "
           "are estimation numbers if it was this one, test scores otherwise.\n";
  return "No samples were held out: every number is on estimation data.\n";
}

std::string headline(const ComparisonInput& in, const Comparison& m) {
  const std::string yu = unit(in.y_unit);
  std::string out =
      "## Headline\n\n" + header_row({"part", "samples", "RMSE" + yu, "fit %", "relative error",
                                      "max |error|" + yu, "mean error" + yu, "RMSE / noise σ"});
  const auto part = [&](const char* name, const ErrorMetrics& p) {
    out += row({name, count(p.n), num(p.rmse), num(p.fit_percent), num(p.relative_error),
                num(p.max_abs_error), num(p.mean_error), ratio_to_sigma(p.rmse, m)});
  };
  part(estimation_name(in), m.parts.estimation);
  if (m.parts.heldout) part("held out", *m.parts.heldout);
  part("all", m.parts.all);
  out +=
      "\nfit % = 100 (1 − ‖y − ŷ‖ / ‖y − ȳ‖); relative error = ‖y − ŷ‖ / ‖y‖. "
      "Errors in units of y" +
      (in.y_unit.empty() ? std::string() : " (" + in.y_unit + ")") +
      ". The model output ŷ is taken as given (normally simulated over the whole record).\n";
  return out + record_sentence(in, m) + "\n";
}

std::string noise_floor(const ComparisonInput& in, const Comparison& m) {
  const ComparedNoiseFloor& f = m.noise_floor;
  std::string how;
  if (f.method == "periodic")
    how = "from repeated periods of the excitation, σ = RMS(y_p − y_{p+1})/√2 over " +
          count(f.pairs) + " sample pairs" +
          (f.period > 0 ? " (period " + count(f.period) + " samples)"
                        : std::string(" (repeated segments)"));
  else if (f.method == "spectral")
    how = "from the output's power in the " + count(f.pairs) +
          " spectral bins where the input has none (from " + num(f.quiet_from / m.sample_time) +
          " Hz up; no repeated periods, and the input reaches above fs/6, where differences "
          "of y keep the signal). A sensor's anti-alias filter lowers the noise there, so σ may "
          "err low";
  else if (f.method == "difference_mad")
    how =
        "from high-order differences of y (no repeated periods found): robust (MAD) estimate, "
        "lowest over orders 2–6 (order " +
        count(f.order) + ")";
  else
    how = "not estimated (fewer than " + std::to_string(kNoiseFloorFewestSamples) + " samples)";
  std::string out =
      "## Noise floor\n\nσ = " + with_unit(num(f.sigma), in.y_unit) + ", " + how + ".\n\n";
  const double r = f.rmse_over_sigma;
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
double ccf_at(const Correlation& ccf, int tau) {
  for (std::size_t i = 0; i < ccf.lags.size(); ++i)
    if (ccf.lags[i] == tau) return ccf.values[i];
  return 0.0;
}

// A peak that falls below half its height within three lags on either
// side: a delay rather than a broad dynamic response.
bool single_peak(const Correlation& ccf, int lag) {
  const double peak = std::abs(ccf_at(ccf, lag));
  return std::abs(ccf_at(ccf, lag - 3)) < 0.5 * peak &&
         std::abs(ccf_at(ccf, lag + 3)) < 0.5 * peak;
}

std::string correlation_verdict(const Comparison& m, double ts) {
  const ResidualAnalysis& r = m.residual;
  const LjungBox& lb = r.ljung_box;
  std::string out =
      "## Residual tests\n\nComputed on the residual e = y − ŷ of the whole record" +
      std::string(m.parts.heldout ? " (estimation and held-out samples together)" : "") + ", N = " +
      count(m.n) + ".\n\n";
  const int acf_out = r.acf.outside;
  if (r.white)
    out += "- **Whiteness**: the residual is white (Ljung–Box Q = " + num(lb.q) + " over " +
           count(lb.lags) + " lags, p = " + p_text(lb.p_value) + " > 0.01); " +
           std::to_string(acf_out) + " of " + std::to_string(r.acf.lags.size()) +
           " autocorrelation lags lie outside the 99 % band ±" + num(r.acf.bound) + ".\n";
  else
    out += "- **Whiteness**: the residual is **not white** (Ljung–Box Q = " + num(lb.q) +
           " over " + count(lb.lags) + " lags, p " + p_text(lb.p_value) +
           " ≤ 0.01): it still has structure "
           "in time; " +
           std::to_string(acf_out) + " of " + std::to_string(r.acf.lags.size()) +
           " autocorrelation lags lie outside the 99 % band ±" + num(r.acf.bound) + ".\n";
  const Correlation& c = r.ccf;
  const int outside = c.outside, lag = r.peak_lag;
  const double peak = ccf_at(c, lag);
  out += "- **Input–residual cross-correlation**: " + std::to_string(outside) + " of " +
         std::to_string(c.lags.size()) + " lags lie outside the 99 % band ±" + num(c.bound) +
         " (about " + num(0.01 * double(c.lags.size())) +
         " expected by chance); the largest is r = " + num(peak) +
         " at τ = " + std::to_string(lag) + ". ";
  const double smooth = r.input_lag1_autocorrelation;
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

std::string segment_table(const ComparisonInput& in, const Comparison& m) {
  std::vector<SegmentErrors> segs = m.by_segment;
  if (segs.empty()) return "";
  // Largest RMSE first; segments without one last.
  std::stable_sort(segs.begin(), segs.end(), [](const SegmentErrors& a, const SegmentErrors& b) {
    const double ra = a.metrics.rmse, rb = b.metrics.rmse;
    return std::isfinite(ra) && (!std::isfinite(rb) || ra > rb);
  });
  const std::size_t shown = std::min(segs.size(), kWorstSegments);
  const std::string yu = unit(in.y_unit);
  std::string out = "### Segments, worst first" +
                    (shown < segs.size()
                         ? " (" + std::to_string(shown) + " of " + std::to_string(segs.size()) + ")"
                         : std::string()) +
                    "\n\n" +
                    header_row({"segment", "part", "samples", "RMSE" + yu, "fit %",
                                "max |error|" + yu, "RMSE / σ"});
  for (std::size_t k = 0; k < shown; ++k) {
    const SegmentErrors& s = segs[k];
    const ErrorMetrics& e = s.metrics;
    const std::string part = s.part == "heldout" ? "held out" : s.part == "estimation" ? estimation_name(in) : s.part;
    out += row({s.segment, part, count(e.n),
                num(e.rmse), num(e.fit_percent), num(e.max_abs_error), ratio_to_sigma(e.rmse, m)});
  }
  return out + "\n";
}

std::string amplitude_table(const ComparisonInput& in, const Comparison& m) {
  const double total = m.parts.all.sse;
  const std::string uu = unit(in.u_unit), yu = unit(in.y_unit);
  std::string out = "### Input amplitude |u − mean u| (mean u = " +
                    with_unit(num(m.u_mean), in.u_unit) +
                    "; equal-width bins)\n\n" +
                    header_row({"bin", "|u − mean u|" + uu, "samples", "RMSE" + yu,
                                "share of samples", "share of SSE"});
  const double n = double(m.n);
  for (const AmplitudeErrors& b : m.by_amplitude)
    out += row({count(b.bin), num(b.u_low) + " – " + num(b.u_high), count(b.metrics.n),
                num(b.metrics.rmse), num(double(b.metrics.n) / n),
                total > 0 ? num(b.metrics.sse / total) : "–"});
  return out + "\n";
}

std::string branch_table(const ComparisonInput& in, const Comparison& m) {
  const std::string yu = unit(in.y_unit);
  std::string out =
      "### Branch (loading Δu > 0, unloading Δu < 0, holding |Δu| ≤ " +
      with_unit(num(m.branch_tolerance), in.u_unit) + ")\n\n" +
      header_row({"branch", "samples", "RMSE" + yu, "mean error" + yu, "max |error|" + yu});
  const auto branch = [&](const char* name, const ErrorMetrics& g) {
    out += row({name, count(g.n), num(g.rmse), num(g.mean_error), num(g.max_abs_error)});
  };
  branch("loading", m.by_branch.loading);
  branch("unloading", m.by_branch.unloading);
  branch("holding", m.by_branch.holding);
  return out + "\n";
}

std::string time_table(const ComparisonInput& in, const Comparison& m) {
  double worst = -1;
  for (const TimeErrors& w : m.by_time) worst = std::max(worst, w.metrics.rmse);
  const std::string yu = unit(in.y_unit);
  std::string out = "### Time windows (worst in bold)\n\n" +
                    header_row({"window", "t [s]", "samples", "RMSE" + yu, "mean error" + yu});
  for (const TimeErrors& w : m.by_time) {
    const ErrorMetrics& e = w.metrics;
    const std::string rmse = e.rmse == worst ? "**" + num(e.rmse) + "**" : num(e.rmse);
    out += row({count(w.window), num(w.t_start) + " – " + num(w.t_end), count(e.n), rmse,
                num(e.mean_error)});
  }
  return out + "\n";
}

// "- Worst segment: ..." when two or more segments have an RMSE.
std::string worst_segment(const ComparisonInput& in, const Comparison& m) {
  if (m.by_segment.size() < 2) return "";
  const SegmentErrors* worst = nullptr;
  std::vector<double> rmse;
  for (const SegmentErrors& s : m.by_segment)
    if (std::isfinite(s.metrics.rmse)) {
      rmse.push_back(s.metrics.rmse);
      if (!worst || s.metrics.rmse > worst->metrics.rmse) worst = &s;
    }
  std::sort(rmse.begin(), rmse.end());
  if (!worst || rmse.empty() || !(rmse[rmse.size() / 2] > 0)) return "";
  return "- Worst segment: " + cell(worst->segment) + " (RMSE " +
         with_unit(num(worst->metrics.rmse), in.y_unit) + ", " +
         num(worst->metrics.rmse / rmse[rmse.size() / 2]) + "× the median segment).\n";
}

// Plain sentences over the breakdown tables that follow.
std::string failure_summary(const ComparisonInput& in, const Comparison& m) {
  std::string out = worst_segment(in, m);
  const ErrorMetrics& top = m.by_amplitude.back().metrics;
  const double total = m.parts.all.sse, n = double(m.n);
  if (total > 0 && n > 0)
    out += "- The largest input amplitudes (top bin) hold " + num(100 * double(top.n) / n) +
           " % of the samples and " + num(100 * top.sse / total) +
           " % of the squared error.\n";
  const BranchErrors& b = m.by_branch;
  if (std::isfinite(b.loading.rmse) && std::isfinite(b.unloading.rmse))
    out += "- RMSE while loading " + with_unit(num(b.loading.rmse), in.y_unit) +
           ", while unloading " + with_unit(num(b.unloading.rmse), in.y_unit) + ".\n";
  return out.empty() ? out : out + "\n";
}

// One row per effect (effect_signatures.hpp): every registered effect's own
// statistic of this residual, in registry order, which is by name
// (registry.hpp) like the keys of metrics.json.
std::string signature_table(const Comparison& m) {
  if (m.signatures.empty()) return "";
  std::string out =
      "## Residual signatures\n\nEvery registered effect's own statistic of this residual, as "
      "declared in its effect file: how strongly the residual shows what that effect would "
      "explain. Each falls towards its no-sign value (0 for a correlation or R², about 1 for a "
      "ratio to chance) as the residual becomes white.\n\n" +
      header_row({"effect", "statistic", "value", "here"}, "llrl");
  for (const EffectSignature& s : m.signatures)
    out += row({"`" + s.effect + "`", s.statistic, num(s.value.value), s.sentence});
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

std::string comparison_markdown(const ComparisonInput& in, const Comparison& metrics,
                                const std::string& title, const std::string& model_text,
                                bool images, const std::string& figure_note) {
  const double ts = metrics.sample_time;
  std::string out = "# " + title + "\n\nModel: `" +
                    (model_text.empty() ? std::string("(not named)") : model_text) + "`. " +
                    count(metrics.n) + " samples, sample time " + num(ts) + " s" +
                    (in.u_unit.empty() ? std::string() : ", input in " + in.u_unit) +
                    (in.y_unit.empty() ? std::string() : ", output in " + in.y_unit) +
                    ". All numbers are in metrics.json.\n\n";
  out += headline(in, metrics) + "## What the record excites\n\n" + metrics.excitation.summary() + "\n\n" +
         (metrics.startup.worth_saying() ? "**" + metrics.startup.sentence() + "**\n\n" : std::string()) +
         noise_floor(in, metrics) + correlation_verdict(metrics, ts);
  out += "## Where the model fails\n\n" + failure_summary(in, metrics) +
         segment_table(in, metrics) + amplitude_table(in, metrics) + branch_table(in, metrics) +
         time_table(in, metrics);
  return out + signature_table(metrics) + figures(images, figure_note);
}

std::vector<fs::path> write_comparison(const fs::path& dir, const ComparisonInput& in,
                                       const Comparison& metrics, const std::string& title,
                                       const std::string& model_text) {
  fs::create_directories(dir);
  std::vector<fs::path> written;
  write_file_atomic(dir / "metrics.json", to_json(metrics).dump(2) + "\n");
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
