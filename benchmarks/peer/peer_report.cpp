#include "benchmarks/peer/peer_report.hpp"

#include <cstdio>
#include <fstream>

#include "framework/core/error.hpp"
#include "framework/report/markdown.hpp"

namespace hystbench::peer {
namespace {

using markdown::num;

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::ofstream open(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw InputError(file.string() + ": cannot write");
  return out;
}

void machine_section(std::ostream& out, const PeerReport& r) {
  const MachineInfo& m = r.machine;
  out << "- CPU: " << m.cpu << ", " << m.cores << " hardware threads\n"
      << "- compiler: " << m.compiler << "\n"
      << "- pagmo " << m.pagmo_version << " (Debian package), hystbench " << m.hystbench_commit << "\n"
      << "- date: " << m.date << "; load average (1, 5, 15 min) at start " << r.load_before
      << ", at end " << r.load_after << "\n"
      << "- command: `" << r.command << "`\n"
      << "- noise floor: SSE " << num(r.noise_floor) << " of the true parameters on the data\n\n";
}

void table(std::ostream& out, const std::vector<PeerRow>& rows, const std::string& section) {
  out << markdown::header_row({"framework", "algorithm", "settings", "budget", "evaluations / trial",
                               "wall s (all trials)", "evaluations / s", "µs / evaluation",
                               "final / noise floor, median", "best", "trials"});
  for (const PeerRow& r : rows) {
    if (r.section != section) continue;
    out << markdown::row({r.framework, r.algorithm, markdown::cell(r.settings), r.budget,
                          fixed(r.evaluations, 0), fixed(r.wall_seconds, 2),
                          fixed(r.evaluations_per_second, 0), fixed(1e6 / r.evaluations_per_second, 2),
                          num(r.median_over_floor), num(r.best_over_floor), std::to_string(r.trials)});
  }
  out << "\n";
}

void protocol_summary(std::ostream& out, const ProtocolTimes& t) {
  const auto line = [&](const std::string& what, double s, long evaluations) {
    out << markdown::row({what, fixed(s, 2), std::to_string(evaluations),
                          fixed(double(evaluations) / s, 0), fixed(t.pagmo_serial / s, 2)});
  };
  out << "Whole protocol (one thread: sums of the trial times above; " << t.threads
      << " threads: wall clock):\n\n"
      << markdown::header_row({"run", "wall s", "evaluations", "evaluations / s",
                               "speed-up over pagmo, one thread"});
  line("hystbench, 1 thread", t.hystbench_serial, t.evaluations);
  line("hystbench, " + std::to_string(t.threads) + " threads", t.hystbench_parallel, t.evaluations);
  line("pagmo, 1 thread", t.pagmo_serial, t.pagmo_evaluations);
  line("pagmo, archipelagos of " + std::to_string(t.threads) + " thread islands", t.pagmo_archipelago,
       t.pagmo_evaluations);
  out << "\nhystbench on " << t.threads << " threads against pagmo's archipelago: "
      << fixed(t.pagmo_archipelago / t.hystbench_parallel, 2) << "x; one thread against one thread: "
      << fixed(t.pagmo_serial / t.hystbench_serial, 2) << "x.\n\n";
}

}  // namespace

void write_markdown(const std::filesystem::path& file, const PeerReport& r) {
  auto out = open(file);
  out << "# Peer comparison: hystbench and pagmo2\n\n";
  machine_section(out, r);
  out << "## Equal evaluation budget, one trial at a time\n\n";
  table(out, r.rows, "equal budget");
  if (r.protocol) {
    out << "## MEDE Table 1 protocol\n\nPer algorithm, one trial at a time:\n\n";
    table(out, r.rows, "MEDE Table 1 protocol");
    protocol_summary(out, *r.protocol);
  }
  out << "## Framework overhead on a trivial fitness\n\n";
  table(out, r.rows, "overhead");
  out << "## GA replacement on sphere-10\n\n"
         "The same operators, box [-100, 100] and budget on both sides; the sphere's optimum is "
         "0, so the last two fitness columns are the final value itself, not a ratio.\n\n";
  table(out, r.rows, "ga replacement");
}

void write_csv(const std::filesystem::path& file, const std::vector<PeerRow>& rows) {
  auto out = open(file);
  out << "section,framework,algorithm,settings,budget,evaluations_per_trial,wall_s,evaluations_per_s,"
         "us_per_evaluation,final_over_noise_floor_median,final_over_noise_floor_best,trials\n";
  const auto quoted = [](const std::string& s) { return "\"" + s + "\""; };
  for (const PeerRow& r : rows)
    out << r.section << ',' << r.framework << ',' << r.algorithm << ',' << quoted(r.settings) << ','
        << r.budget << ',' << fixed(r.evaluations, 1) << ',' << fixed(r.wall_seconds, 4) << ','
        << fixed(r.evaluations_per_second, 1) << ',' << fixed(1e6 / r.evaluations_per_second, 4)
        << ',' << r.median_over_floor << ',' << r.best_over_floor << ',' << r.trials << '\n';
}

}  // namespace hystbench::peer
