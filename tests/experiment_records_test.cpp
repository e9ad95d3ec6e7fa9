// Records an experiment makes on demand (framework/cli/experiment_records.hpp):
// the bundled SVR and tracking experiments must run from a clean checkout.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;
using test_support::contains;
using test_support::read;
using test_support::TempDir;

// The built program run inside `dir`, as a user in that folder runs it.
test_support::Outcome run_in(const fs::path& dir, const std::string& args) {
  return test_support::hystbench(args, dir.string());
}

// Everything after the two comment lines, which name the file's own path.
std::string rows_of(const fs::path& csv) {
  const std::string text = read(csv);
  return text.substr(text.find('\n', text.find('\n') + 1) + 1);
}

constexpr const char* kParams =
    R"({"gain": 0.1, "hysteresis.A": 0.05, "hysteresis.beta": 0.01, "hysteresis.gamma": 0.002,
        "msd.period": 0.0025, "msd.zeta": 0.3})";
constexpr const char* kExcitation =
    R"({"sample_rate": 2000, "segments": [{"type": "sine", "frequency": 5, "amplitude": 75, "offset": 75,
        "phase_deg": -90, "duration": 0.4, "label": "train"}]})";

// A folder with the files a recipe names, an experiment naming the record
// and a records file; `greybox` is a file the recipes do not make.
void write_experiment_folder(const TempDir& dir, const std::string& recipe_extra = "") {
  dir.write("actuator.json", kParams);
  dir.write("train.excitation.json", kExcitation);
  dir.write("records.json",
            R"({"made_by": "scripts/make_my_data.sh", "simulate": [{"out": "data/train.csv",
                "model": "hysteresis,msd", "params": "actuator.json", "excitation": "train.excitation.json",
                "noise": 0.005, "resolution": 0.1, "seed": 202, "input_unit": "V", "output_unit": "µm")" +
                recipe_extra + "}]}");
  dir.write("experiment.json", R"({"name": "x", "records": "records.json",
                                   "stage1": {"data": "data/train.csv"}, "tests": ["data/train.csv"],
                                   "hyperparameters": {"epsilon": 0.01, "C": 10, "sigma": 30},
                                   "greybox": "greybox/fit.json"})");
}

// The missing record is simulated before the experiment is read, the same
// rows as `hystbench simulate` with the recipe's options; a missing file the
// recipes do not cover names the script that makes it.
TEST(ExperimentRecords, MissingRecordIsSimulatedAndOtherMissingFilesNameTheirScript) {
  const TempDir dir;
  write_experiment_folder(dir);
  const test_support::Outcome svr = run_in(dir.path(), "svr experiment.json --out out --quiet");
  EXPECT_EQ(svr.code, 2) << svr.output;
  EXPECT_TRUE(contains(svr.output, "made the missing record data/train.csv")) << svr.output;
  EXPECT_TRUE(contains(svr.output, "greybox/fit.json\": file not found")) << svr.output;
  EXPECT_TRUE(contains(svr.output, "scripts/make_my_data.sh makes the files this experiment reads")) << svr.output;
  ASSERT_TRUE(fs::exists(dir.path() / "data/train.csv"));
  EXPECT_FALSE(fs::exists(dir.path() / "out")) << "bad input: nothing written to --out";

  const test_support::Outcome simulate = run_in(dir.path(),
                              "simulate --model hysteresis,msd --params actuator.json --excitation "
                              "train.excitation.json --noise 0.005 --resolution 0.1 --seed 202 "
                              "--input-unit V --output-unit µm --out data/again.csv");
  ASSERT_EQ(simulate.code, 0) << simulate.output;
  EXPECT_EQ(rows_of(dir.path() / "data/train.csv"), rows_of(dir.path() / "data/again.csv"));
  EXPECT_TRUE(contains(read(dir.path() / "data/train.csv"),
                       "Regenerate: hystbench simulate --model hysteresis,msd --params actuator.json "
                       "--excitation train.excitation.json --noise 0.005 --seed 202 --resolution 0.1 "
                       "--input-unit V --output-unit µm --out data/train.csv\n"));

  // Present now: not made again.
  const test_support::Outcome again = run_in(dir.path(), "svr experiment.json --out out --quiet");
  EXPECT_FALSE(contains(again.output, "made the missing record")) << again.output;
}

TEST(ExperimentRecords, ABadRecipeIsRefusedBeforeAnythingIsWritten) {
  const TempDir dir;
  write_experiment_folder(dir, R"(, "noize": 0.1)");
  const test_support::Outcome svr = run_in(dir.path(), "svr experiment.json --out out --quiet");
  EXPECT_EQ(svr.code, 2) << svr.output;
  EXPECT_TRUE(contains(svr.output, "records.json.simulate[0]")) << svr.output;
  EXPECT_TRUE(contains(svr.output, "noize")) << svr.output;
  EXPECT_FALSE(fs::exists(dir.path() / "data")) << "nothing simulated on a bad recipe";
}

}  // namespace
}  // namespace hystbench
