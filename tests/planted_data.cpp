// Writes a measurement with physics the effect catalog lacks
// (tests/planted_physics.hpp), for the propose walkthrough and
// benchmarks/beyond_catalog.sh:
//
//   hystbench_planted_data CASE OUT.csv [SAMPLES]
//
// CASE: rate_gain (a gain that grows with the drive rate), cubic_stiffness
// (a hardening spring inside the dynamics), parallel_play (a play operator beside
// the gain), drive_stiffness (a spring that stiffens with the drive) or
// quadratic_damping (a drag that grows with the speed); or, which no term of
// the library expresses: gain_drift (a gain that drifts with time),
// coulomb_friction (dry friction: a force that jumps with the direction of
// motion) or rate_dependent_play (a play operator whose width grows with
// the drive rate).
// OUT.truth.json beside it holds the planted system and the noise sd, as
// `hystbench simulate` writes one.
#include <fstream>
#include <iostream>
#include <string>

#include "framework/io/measurement.hpp"
#include "tests/planted_physics.hpp"

namespace {

bool planted_case(const std::string& name, hystbench::planted::System& s) {
  if (name == "rate_gain")
    s.rate_gain = 0.001;
  else if (name == "cubic_stiffness")
    s.cubic = 0.01;
  else if (name == "parallel_play")
    s.play_gain = 0.2;
  else if (name == "drive_stiffness")
    s.drive_stiffness = 0.03;
  else if (name == "quadratic_damping")
    s.quadratic_damping = 1e-6;
  else if (name == "gain_drift")
    s.gain_drift = 0.05;
  else if (name == "coulomb_friction")
    s.coulomb = 0.05;
  else if (name == "rate_dependent_play") {
    s.play_gain = 0.2;
    s.play_radius = 0.1;
    s.play_width_rate = 0.01;
  }
  else
    return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: hystbench_planted_data rate_gain|cubic_stiffness|parallel_play|drive_stiffness|"
                 "quadratic_damping|gain_drift|coulomb_friction|rate_dependent_play OUT.csv [SAMPLES]\n";
    return 2;
  }
  hystbench::planted::System s;
  if (!planted_case(argv[1], s)) {
    std::cerr << "hystbench_planted_data: unknown case '" << argv[1]
              << "'; known: rate_gain, cubic_stiffness, parallel_play, drive_stiffness, quadratic_damping, "
                 "gain_drift, coulomb_friction, rate_dependent_play\n";
    return 2;
  }
  const long n = argc == 4 ? std::stol(argv[3]) : 6000;
  if (n < 100) {
    std::cerr << "hystbench_planted_data: SAMPLES must be at least 100\n";
    return 2;
  }
  const double ts = 1e-3;
  const hystbench::Measurement m = hystbench::planted::simulate(s, hystbench::planted::multisine(n, ts), ts);
  const std::string out = argv[2];
  hystbench::write_measurement(out, m, {"planted case " + std::string(argv[1]) + " (tests/planted_physics.hpp)"});
  const nlohmann::json truth = {{"planted", argv[1]},
                                {"system",
                                 {{"gain", s.gain}, {"rate_gain", s.rate_gain}, {"gain_drift", s.gain_drift}, {"period", s.period},
                                  {"zeta", s.zeta}, {"cubic", s.cubic}, {"play_gain", s.play_gain},
                                  {"play_radius", s.play_radius}, {"play_width_rate", s.play_width_rate},
                                  {"drive_stiffness", s.drive_stiffness}, {"quadratic_damping", s.quadratic_damping},
                                  {"coulomb", s.coulomb}}},
                                {"noise", {{"sd", s.noise}}}};
  const std::string stem = out.size() > 4 && out.substr(out.size() - 4) == ".csv" ? out.substr(0, out.size() - 4) : out;
  std::ofstream(stem + ".truth.json") << truth.dump(2) << "\n";
  return 0;
}
