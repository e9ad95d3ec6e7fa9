// Cost of tracking (framework/tracking/): the design step (mixed-sensitivity
// synthesis, reduction to 3 states, the checks and the Tustin maps) on the
// 1260 Hz nominal model of the tests, and one second of the closed loop at
// 10 kHz (plant hysteresis,asymmetry,msd; inverse of a model of it a few
// per cent off; the reduced H∞ controller and the feedforward Wr).
// Targets (issue "precision tracking"): design below 50 ms, one second of
// loop below 20 ms on one core.
#include <benchmark/benchmark.h>

#include "framework/control/model_stream.hpp"
#include "framework/robust/linear_system.hpp"
#include "framework/tracking/hinf_design.hpp"
#include "framework/tracking/tracking_loop.hpp"

namespace {

using namespace hystbench;

void BM_TrackingDesign(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(reference_design().gamma);
}
BENCHMARK(BM_TrackingDesign)->Unit(benchmark::kMillisecond);

nlohmann::json actuator(double scale) {
  nlohmann::json p = {{"gain", 0.1},           {"hysteresis.A", 0.05}, {"hysteresis.beta", 0.01},
                      {"hysteresis.gamma", 0.002}, {"asymmetry.d2", 0.0002}, {"msd.period", 0.0025},
                      {"msd.zeta", 0.3}};
  for (auto& [name, value] : p.items()) value = value.get<double>() * scale;
  return {{"model", "hysteresis,asymmetry,msd"}, {"parameters", p}};
}

void BM_TrackingLoopOneSecond(benchmark::State& state) {
  const double ts = 1e-4;
  const auto identified = read_identified(actuator(1.03), ".", "identified").make(ts);
  const ModelStream plant = model_stream(actuator(1.0), ".", ts, "plant");
  const NominalDynamics nominal = identify_dynamics(*identified, ts, 2, 1, 1, "nominal");
  const ControllerDesign design = design_controller(nominal, seed_uncertainty_weight(), DesignOptions{});
  const InverseCompensator inverse(*identified, "identified", 0.0, 150.0, 1e-6);
  const TrackingSetup setup{ts, plant.stream.get(), &inverse, &nominal.feedforward, {0.02, 0.1}};
  TrackingController controller;
  controller.kind = TrackingController::Kind::Hinf;
  controller.feedback = design.reduced_discrete;
  const TrackingReference reference = make_reference({50.0}, 6.0, 9.5, "reference");
  const ScoreWindow window{0.9, 0.1};  // 1 s in all
  for (auto _ : state)
    benchmark::DoNotOptimize(run_tracking(setup, controller, reference, window, 1).score.armse);
}
BENCHMARK(BM_TrackingLoopOneSecond)->Unit(benchmark::kMillisecond);

}  // namespace
