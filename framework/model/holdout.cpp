#include "framework/model/holdout.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/io/segment_runs.hpp"

namespace hystbench {
namespace {

struct SegmentSpan {
  std::string label;
  Eigen::Index begin = 0, end = 0;  // [begin, end), first occurrence onwards
  double frequency = 0.0;           // dominant input frequency, Hz
};

double zero_crossing_frequency(const ModelData& d, Eigen::Index begin, Eigen::Index end) {
  const auto n = end - begin;
  if (n < 2) return 0.0;
  const double mean = d.u.segment(begin, n).mean();
  long crossings = 0;
  for (Eigen::Index k = begin + 1; k < end; ++k)
    if ((d.u[k - 1] - mean) * (d.u[k] - mean) < 0.0) ++crossings;
  return crossings / (2.0 * double(n) * d.sample_time);
}

// Contiguous runs of equal labels, in time order, with their frequencies.
std::vector<SegmentSpan> segment_spans(const ModelData& d) {
  std::vector<SegmentSpan> spans;
  for (const SegmentRun& run : segment_runs(d.segment, d.size()))
    spans.push_back({run.label, run.begin, run.end, zero_crossing_frequency(d, run.begin, run.end)});
  return spans;
}

void hold_out_tail(ModelData& d, Eigen::Index begin, Eigen::Index end, double fraction) {
  const auto n = end - begin;
  const auto held = static_cast<Eigen::Index>(std::floor(fraction * double(n)));
  d.estimation.segment(end - held, held).setZero();
}

constexpr double kTailFraction = 0.25;
constexpr int kBlocksWithoutSegments = 8;

void auto_holdout(ModelData& d) {
  if (d.segment.empty()) {
    for (int b = 0; b < kBlocksWithoutSegments; ++b)
      hold_out_tail(d, d.size() * b / kBlocksWithoutSegments,
                    d.size() * (b + 1) / kBlocksWithoutSegments, kTailFraction);
    return;
  }
  for (const auto& s : segment_spans(d)) hold_out_tail(d, s.begin, s.end, kTailFraction);
}

void by_frequency_holdout(ModelData& d) {
  const auto spans = d.segment.empty() ? std::vector<SegmentSpan>{} : segment_spans(d);
  const auto n = spans.size();
  if (n < 4) return auto_holdout(d);
  std::vector<std::size_t> rank(n);
  for (std::size_t i = 0; i < n; ++i) rank[i] = i;
  std::stable_sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) {
    return spans[a].frequency < spans[b].frequency;
  });
  const std::size_t m = std::max<std::size_t>(1, std::lround(double(n) / 4.0));
  for (std::size_t i = 0; i < m; ++i) {
    const auto r = static_cast<std::size_t>((double(i) + 0.5) * double(n) / double(m));
    const auto& s = spans[rank[std::min(r, n - 2)]];
    d.estimation.segment(s.begin, s.end - s.begin).setZero();
  }
}

}  // namespace

namespace {

// "…+warmup:N": the count, or InputError naming `where`.
Eigen::Index parse_warmup(const std::string& text, const std::string& where) {
  const std::string count = text.substr(text.find(':') + 1);
  try {
    std::size_t used = 0;
    const long n = std::stol(count, &used);
    if (used == count.size() && n >= 0) return n;
  } catch (const std::exception&) {
  }
  throw InputError(where + " " + text + ": expected a sample count (0 or more) after 'warmup:'");
}

}  // namespace

HoldoutSpec HoldoutSpec::parse(const std::string& given, const std::string& where) {
  const std::string held = "+held";
  const bool held_start =
      given.size() > held.size() && given.compare(given.size() - held.size(), held.size(), held) == 0;
  const std::string full = held_start ? given.substr(0, given.size() - held.size()) : given;
  const auto plus = full.find("+warmup:");
  const std::string text = full.substr(0, plus);
  HoldoutSpec s = parse_part(text, where);
  if (plus != std::string::npos) s.warmup = parse_warmup(full.substr(plus + 1), where);
  s.held_start = held_start;
  return s;
}

HoldoutSpec HoldoutSpec::parse_part(const std::string& text, const std::string& where) {
  const std::string forms =
      "auto, none, last:FRACTION (e.g. last:0.25), segments:LABEL,LABEL or by-frequency";
  HoldoutSpec s;
  const auto colon = text.find(':');
  const std::string head = text.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (text == "auto") return s;
  if (text == "by-frequency") {
    s.mode = Mode::ByFrequency;
    return s;
  }
  if (text == "none") {
    s.mode = Mode::None;
    return s;
  }
  if (head == "last") {
    s.mode = Mode::Last;
    try {
      std::size_t used = 0;
      s.fraction = std::stod(rest, &used);
      if (used != rest.size()) throw std::invalid_argument(rest);
    } catch (const std::exception&) {
      throw InputError(where + " " + text + ": expected a number after 'last:'");
    }
    if (!(s.fraction > 0.0 && s.fraction < 1.0))
      throw InputError(where + " " + text + ": the fraction must lie strictly between 0 and 1");
    return s;
  }
  if (head == "segments" && !rest.empty()) {
    s.mode = Mode::Segments;
    std::string item;
    for (std::size_t i = 0; i <= rest.size(); ++i) {
      if (i == rest.size() || rest[i] == ',') {
        if (!item.empty()) s.segments.push_back(item);
        item.clear();
      } else {
        item += rest[i];
      }
    }
    return s;
  }
  throw InputError(where + " " + text + ": not a hold-out; use " + forms);
}

std::string HoldoutSpec::text() const {
  return part_text() + (warmup > 0 ? "+warmup:" + std::to_string(warmup) : "") +
         (held_start ? "+held" : "");
}

std::string HoldoutSpec::part_text() const {
  switch (mode) {
    case Mode::Auto: return "auto";
    case Mode::None: return "none";
    case Mode::Last: return "last:" + number_text(fraction);
    case Mode::Segments: return "segments:" + join(segments, ",");
    case Mode::ByFrequency: return "by-frequency";
  }
  return "auto";
}

namespace {

void apply_warmup(ModelData& d, Eigen::Index warmup, bool held_start) {
  if (warmup >= d.size())
    throw InputError("--warmup " + std::to_string(warmup) + ": the record has only " +
                     std::to_string(d.size()) + " samples; the warm-up must leave some to score");
  if (held_start && warmup == 0)
    throw InputError(
        "--initial-state held: the held level is matched to the warm-up samples; give --warmup N "
        "(N of 1 or more, e.g. 5), or --initial-state rest");
  d.estimation.head(warmup).setZero();
  d.warmup = warmup;
  d.held_start = held_start;
}

}  // namespace

void apply_holdout(ModelData& d, const HoldoutSpec& spec) {
  d.estimation.setOnes(d.size());
  switch (spec.mode) {
    case HoldoutSpec::Mode::None: break;
    case HoldoutSpec::Mode::Auto: auto_holdout(d); break;
    case HoldoutSpec::Mode::ByFrequency: by_frequency_holdout(d); break;
    case HoldoutSpec::Mode::Last: hold_out_tail(d, 0, d.size(), spec.fraction); break;
    case HoldoutSpec::Mode::Segments:
      if (d.segment.empty())
        throw InputError("--holdout " + spec.text() + ": the data have no segment column");
      for (const auto& label : spec.segments) {
        bool found = false;
        for (Eigen::Index k = 0; k < d.size(); ++k)
          if (d.segment[k] == label) d.estimation[k] = 0.0, found = true;
        if (!found) throw InputError("--holdout: no segment '" + label + "' in the data");
      }
      break;
  }
  apply_warmup(d, spec.warmup, spec.held_start);
  if (d.estimation_count() < 2)
    throw InputError("--holdout " + spec.text() + ": leaves fewer than two samples to fit");
}

namespace {

std::string by_frequency_text(const ModelData& d, const std::string& count) {
  std::set<std::string> held;
  const Eigen::VectorXd mask = d.heldout_mask();
  for (Eigen::Index k = 0; k < d.size(); ++k)
    if (mask[k] != 0.0) held.insert(d.segment[k]);
  return count + ": whole segments spread over the frequency band (" +
         join(std::vector<std::string>(held.begin(), held.end()), ", ") +
         "); a test of extrapolation to frequencies the fit never sees.";
}

std::string describe_held_part(const ModelData& d, const HoldoutSpec& spec) {
  const std::string count = std::to_string(d.heldout_count()) + " of " + std::to_string(d.size()) +
                            " samples held out";
  switch (spec.mode) {
    case HoldoutSpec::Mode::None:
      return "Nothing held out (--holdout none): every error is on the data the fit saw.";
    case HoldoutSpec::Mode::ByFrequency:
      if (!d.segment.empty() && segment_spans(d).size() >= 4) return by_frequency_text(d, count);
      [[fallthrough]];  // fewer than four segments: the auto hold-out was used
    case HoldoutSpec::Mode::Auto:
      return count + (d.segment.empty() ? ": the last quarter of each eighth of the record"
                                        : ": the last quarter of every segment") +
             ", so the held-out part spans every excitation frequency and amplitude the fit "
             "sees and judges the model where it was fitted, not where it extrapolates.";
    case HoldoutSpec::Mode::Last:
      return count + ": the last " + number_text(100 * spec.fraction) + " % of the record.";
    case HoldoutSpec::Mode::Segments:
      return count + ": the segments " + join(spec.segments, ", ") +
             " (chosen by the user); effects are selected on how they extrapolate to them.";
  }
  return count + ".";
}

}  // namespace

std::string describe_holdout(const ModelData& d, const HoldoutSpec& spec) {
  const std::string held = describe_held_part(d, spec);
  if (d.warmup == 0) return held;
  const std::string warm = held + " The first " + std::to_string(d.warmup) +
                           " samples are a warm-up (--warmup): the model runs through them to "
                           "reach the record's state, and no error counts them.";
  if (!d.held_start) return warm;
  return warm + " The record starts where a long-held input leaves the model, at the level that "
                "matches the warm-up (--initial-state held).";
}

}  // namespace hystbench
