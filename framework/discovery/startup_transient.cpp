#include "framework/discovery/startup_transient.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/core/text.hpp"
#include "framework/io/json_number.hpp"
#include "framework/stats/descriptive.hpp"

namespace hystbench {

namespace {

// The first hundredth of the record (at least 5 samples): an error there
// that is mostly its mean, and large against the whole record's, is a start
// level the model does not share, which a loop or a missing effect is not.
void mark_start_level(StartupTransient& t, const Eigen::VectorXd& e) {
  const Eigen::Index k = std::max<Eigen::Index>(5, e.size() / 100);
  if (e.size() < 4 * k) return;
  const double rms = std::sqrt(e.squaredNorm() / double(e.size()));
  const double first = std::sqrt(e.head(k).squaredNorm() / double(k));
  t.start_ratio = first / rms;
  t.starts_away = t.start_ratio >= kStartLevelRatio && std::abs(e.head(k).mean()) >= 0.8 * first;
}

double block_rms(const Eigen::VectorXd& e, Eigen::Index begin, Eigen::Index block) {
  return std::sqrt(e.segment(begin, block).squaredNorm() / double(block));
}

// The median RMS of the record's blocks of `block` samples: the level the
// error settles to, which the transient's own large blocks barely move.
double typical_block_rms(const Eigen::VectorXd& e, Eigen::Index block) {
  std::vector<double> rms;
  for (Eigen::Index b = 0; b + block <= e.size(); b += block) rms.push_back(block_rms(e, b, block));
  return rms.empty() ? 0.0 : stats::median(rms);
}

// Where the first excited part's error has fallen to the record's level and
// stays there for kSettledBlocks blocks (a ringing error crosses zero, so one
// quiet block proves nothing). A lightly damped resonance started at rest
// rings for as long as its decay takes, which may be many excitation periods:
// Silverbox's estimation record, caught mid-motion, rings for about 130
// samples, so a warm-up of one period leaves most of the transient in the
// fit. Never before `floor` (the end of the first period). An error that
// settles only in the part's second half, or not at all, is no start-up
// transient to skip (the model is wrong there, or the part is too short to
// tell), and then the answer is `floor`.
Eigen::Index settled_at(const Eigen::VectorXd& e, const ExcitedPart& p, Eigen::Index period, Eigen::Index floor) {
  const Eigen::Index block = std::max<Eigen::Index>(8, period / 2);
  const Eigen::Index latest = p.begin + (p.end - p.begin) / 2;
  const double level = kSettledRatio * typical_block_rms(e, block);
  Eigen::Index quiet = 0;
  for (Eigen::Index b = floor; b + block <= p.end; b += block) {
    quiet = block_rms(e, b, block) <= level ? quiet + 1 : 0;
    const Eigen::Index start = b - std::max<Eigen::Index>(quiet - 1, 0) * block;
    if (start > latest) break;
    if (quiet == kSettledBlocks) return start;
  }
  return floor;
}

}  // namespace

StartupTransient find_startup_transient(const Eigen::VectorXd& e, const ExcitationContent& excitation,
                                        Eigen::Index first_sample) {
  StartupTransient t;
  t.warmup = t.first_period_end = first_sample;
  const double total = e.squaredNorm();
  if (!(total > 0) || !std::isfinite(total) || excitation.parts.empty()) return t;  // a diverged model has no transient to name
  double first = 0;
  Eigen::Index samples = 0;
  bool first_part = true;
  for (const auto& p : excitation.parts) {
    if (!(p.frequency_hz > 0)) continue;
    const auto period = Eigen::Index(std::ceil(1.0 / (p.frequency_hz * excitation.sample_time)));
    const Eigen::Index end = std::min(p.end, p.begin + period);
    first += e.segment(p.begin, end - p.begin).squaredNorm();
    samples += end - p.begin;
    if (first_part) {
      t.first_period_end = first_sample + end;
      t.warmup = first_sample + settled_at(e, p, period, end);
      first_part = false;
    }
  }
  t.error_share = first / total;
  t.sample_share = double(samples) / double(e.size());
  t.dominates = t.error_share >= kTransientErrorShare &&
                t.error_share >= kTransientConcentration * t.sample_share && t.sample_share < 0.5;
  mark_start_level(t, e);
  return t;
}

std::string StartupTransient::sentence() const {
  if (!worth_saying()) return "";
  if (!dominates)
    return "The record starts away from where the model starts: the first samples' error is a "
           "level " + format_number("%.1f", start_ratio) +
           " times the RMSE. A record that starts away from rest (a tank half full, an actuator "
           "held at a voltage) is started there by --warmup N --initial-state held (N: a few "
           "samples, whose outputs set the level).";
  return "A start-up transient dominates the error: the first period of each excited part holds " +
         format_number("%.0f", 100 * error_share) + " % of the squared error in " +
         format_number("%.1f", 100 * sample_share) +
         " % of the samples. A model started at rest does not follow the actuator until its states "
         "have caught up; no effect cures that. Fit with --warmup " + std::to_string(warmup) +
         " (" + (warmup > first_period_end ? std::string("where the error after the first excited part's start "
                                                       "falls to the level of the rest of the record")
                                           : std::string("the first excited part's first period")) +
         "), or trim the record; a record that starts "
         "away from rest (a level held before it) is started there by --initial-state held.";
}

nlohmann::json StartupTransient::to_json() const {
  return {{"dominates", dominates},
          {"error_share", number_or_null(error_share)},
          {"sample_share", number_or_null(sample_share)},
          {"warmup", warmup},
          {"first_period_end", first_period_end},
          {"starts_away", starts_away},
          {"start_ratio", number_or_null(start_ratio)},
          {"sentence", sentence()}};
}

}  // namespace hystbench
