// Measurements in MAT files: read wherever a CSV is, in every MAT version,
// through struct paths, and the same fit as the CSV they were made from.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "framework/core/error.hpp"
#include "framework/io/mat_file.hpp"
#include "framework/io/measurement.hpp"
#include "run_command.hpp"
#include "source_tree.hpp"
#include "temp_dir.hpp"

namespace hystbench {
namespace {
namespace fs = std::filesystem;
using test_support::contains;
using test_support::hystbench;
using test_support::kSourceRoot;
using test_support::TempDir;

const fs::path kDefault = kSourceRoot / "problems/hammerstein/data/default.csv";
const fs::path kCorpus = kSourceRoot / "tests/bad_inputs";

void expect_same(const Measurement& a, const Measurement& b) {
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.u, b.u);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.segment, b.segment);
  EXPECT_EQ(a.sample_time, b.sample_time);
}

TEST(MatMeasurement, EveryVersionReadsBackTheSameNumbers) {
  TempDir tmp;
  const Measurement csv = read_measurement(kDefault);
  for (const auto format : {MatFormat::V5, MatFormat::V7, MatFormat::V73}) {
    const fs::path file = tmp.path() / ("default_" + std::to_string(int(format)) + ".mat");
    write_mat_file(file, {{"t", csv.t}, {"u", csv.u}, {"y", csv.y}}, {{"segment", csv.segment}},
                   format);
    expect_same(read_measurement(file), csv);
  }
}

TEST(MatMeasurement, WriteMeasurementGoesByTheName) {
  TempDir tmp;
  const Measurement csv = read_measurement(kDefault);
  write_measurement(tmp.path() / "copy.mat", csv);
  EXPECT_TRUE(is_mat_file(tmp.path() / "copy.mat"));
  expect_same(read_measurement(tmp.path() / "copy.mat"), csv);
}

TEST(MatMeasurement, StructPathsReachControlDeskAndSimulinkLayouts) {
  const Measurement good = read_measurement(kCorpus / "good.csv");
  const auto controldesk = read_measurement(
      kCorpus / "controldesk_record.mat",
      ColumnMap::parse("t=rec.X.Data,u=rec.Y(1).Data,y=rec.Y(2).Data"));
  expect_same(controldesk, good);
  const auto simulink = read_measurement(
      kCorpus / "simulink_structure.mat",
      ColumnMap::parse("t=yout.time,u=yout.signals(1).values,y=yout.signals(2).values"));
  expect_same(simulink, good);
}

TEST(MatMeasurement, StructArrayWithoutAnElementSaysWhichToPick) {
  try {
    read_measurement(kCorpus / "controldesk_record.mat",
                     ColumnMap::parse("t=rec.X.Data,u=rec.Y.Data,y=rec.Y(2).Data"));
    FAIL() << "read a struct array without an element";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "rec.Y is a 1×2 struct array; pick one element, e.g. rec.Y(1).Data"))
        << e.what();
  }
}

// The bundled data as a MAT file give the fit of the CSV, to the last bit.
TEST(MatMeasurement, FitOfTheBundledDataAsMatEqualsTheCsvFit) {
  TempDir tmp;
  const fs::path mat = tmp.path() / "default.mat";
  write_measurement(mat, read_measurement(kDefault));
  // The truth file beside the data gives the units, as beside the CSV.
  fs::copy_file(kDefault.parent_path() / "default.truth.json", tmp.path() / "default.truth.json");
  const std::string options = " --model hysteresis,msd --restarts 1 --evaluations 600 --seed 3 ";
  ASSERT_EQ(hystbench("fit --data " + kDefault.string() + options + "--out " +
                      (tmp.path() / "csv").string()).code, 0);
  const auto r = hystbench("fit --data " + mat.string() + options + "--out " +
                           (tmp.path() / "mat").string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto csv_fit = nlohmann::json::parse(test_support::read(tmp.path() / "csv/fit.json"));
  const auto mat_fit = nlohmann::json::parse(test_support::read(tmp.path() / "mat/fit.json"));
  EXPECT_EQ(csv_fit["parameters"], mat_fit["parameters"]);
  EXPECT_EQ(csv_fit["errors"], mat_fit["errors"]);
  EXPECT_EQ(csv_fit["metrics"], mat_fit["metrics"]);
}

TEST(MatMeasurement, CompareAndSimulateWriteMatFiles) {
  TempDir tmp;
  const fs::path fit = tmp.path() / "fit";
  ASSERT_EQ(hystbench("fit --data " + kDefault.string() + " --model msd --restarts 1 --evaluations "
                      "300 --out " + fit.string()).code, 0);
  const fs::path out = tmp.path() / "compare.mat";
  const auto r = hystbench("compare --data " + kDefault.string() + " --fit " +
                           (fit / "fit.json").string() + " --out " +
                           (tmp.path() / "compare").string() + " --mat " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const MatReader reader(out);
  const Measurement data = read_measurement(kDefault);
  // The data as compare scored them: back from normalised units, so equal to the
  // last bits only.
  EXPECT_TRUE(reader.vector("y", "y").isApprox(data.y, 1e-14));
  const Eigen::VectorXd residual = reader.vector("y", "y") - reader.vector("y_model", "y_model");
  EXPECT_EQ(reader.vector("residual", "residual"), residual);
  const fs::path simulated = tmp.path() / "simulated.mat";
  const fs::path bundled = kSourceRoot / "problems/hammerstein/data";
  const auto s = hystbench("simulate --params " + (bundled / "default.params.json").string() +
                           " --excitation " + (bundled / "default.excitation.json").string() +
                           " --out " + simulated.string());
  ASSERT_EQ(s.code, 0) << s.output;
  EXPECT_GT(read_measurement(simulated).size(), 1000);
  EXPECT_TRUE(fs::exists(tmp.path() / "simulated.truth.json"));
}

TEST(MatMeasurement, MatOptionMustNameAMatFile) {
  TempDir tmp;
  const auto r = hystbench("compare --data " + kDefault.string() + " --fit x.json --out " +
                           (tmp.path() / "c").string() + " --mat out.csv");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.output, "--mat: out.csv: a MAT file's name ends in .mat")) << r.output;
  EXPECT_FALSE(fs::exists(tmp.path() / "c"));
}

}  // namespace
}  // namespace hystbench
