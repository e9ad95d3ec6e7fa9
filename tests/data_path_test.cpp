// Where a data file named in an experiment is found.
#include "framework/io/data_path.hpp"

#include <gtest/gtest.h>

#include "framework/core/error.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;

TEST(DataPath, FoundBesideTheExperimentOrInAFolderAboveIt) {
  test_support::TempDir tmp;
  fs::create_directories(tmp.path() / "repo/benchmarks/experiments");
  fs::create_directories(tmp.path() / "repo/data");
  tmp.write("repo/data/a.csv", "t,u,y\n");
  tmp.write("repo/benchmarks/experiments/b.csv", "t,u,y\n");
  const fs::path base = tmp.path() / "repo/benchmarks/experiments";
  EXPECT_EQ(resolve_data_path("b.csv", base, "problem.data"), base / "b.csv");
  EXPECT_EQ(resolve_data_path("data/a.csv", base, "problem.data"), tmp.path() / "repo/data/a.csv");
}

TEST(DataPath, MissingFileNamesTheKeyAndWhereItLooked) {
  test_support::TempDir tmp;
  try {
    resolve_data_path("nowhere/x.csv", tmp.path(), "problem.data");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("problem.data = \"nowhere/x.csv\": file not found"), std::string::npos) << what;
    EXPECT_NE(what.find("the folders above it"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace hystbench
