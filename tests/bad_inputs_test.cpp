// The bad-input corpus in tests/bad_inputs/: every file listed in its
// manifest.json as rejected must be refused by the real program with exit
// code 2, one message naming the place and the fix, and no output left
// behind; every file listed as accepted must be read with the values given.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "framework/io/measurement.hpp"
#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {
namespace fs = std::filesystem;
using test_support::contains;

const fs::path kCorpus = fs::path(HYSTBENCH_SOURCE_DIR) / "tests" / "bad_inputs";

nlohmann::json manifest_part(const char* part) {
  std::ifstream in(kCorpus / "manifest.json");
  return nlohmann::json::parse(in).at(part);
}

// One manifest entry; printed by its file name in test listings.
struct Entry {
  nlohmann::json json;
  const nlohmann::json& at(const char* key) const { return json.at(key); }
};
void PrintTo(const Entry& e, std::ostream* os) { *os << e.json.at("file").get<std::string>(); }

std::vector<Entry> entries(const char* part) {
  std::vector<Entry> out;
  for (const auto& j : manifest_part(part)) out.push_back({j});
  return out;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::set<std::string> corpus_listing() {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(kCorpus)) names.insert(e.path().string());
  return names;
}

// gtest names: letters, digits and underscores only, unique per entry.
std::string test_name(const ::testing::TestParamInfo<Entry>& info) {
  std::string name = std::to_string(info.index) + "_" + info.param.at("file").get<std::string>();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class RejectedInput : public ::testing::TestWithParam<Entry> {};

TEST_P(RejectedInput, ExitsWithOneMessageAndWritesNothing) {
  const auto& entry = GetParam();
  test_support::TempDir temp;
  const fs::path out = temp.path() / "out";
  std::string command = entry.at("command");
  command = replace_all(command, "{file}", (kCorpus / entry.at("file").get<std::string>()).string());
  command = replace_all(command, "{dir}", kCorpus.string());
  command = replace_all(command, "{out}", out.string());
  const auto before = corpus_listing();

  const auto o = test_support::hystbench(command);
  // `track` exists only where SLICOT was found at build time.
  if (entry.json.value("requires", "") == "slicot" && contains(o.output, "built without SLICOT"))
    GTEST_SKIP() << "this hystbench was built without SLICOT";

  SCOPED_TRACE(entry.at("why").get<std::string>() + ": hystbench " + command);
  EXPECT_EQ(o.code, entry.at("exit").get<int>()) << o.output;
  for (const auto& fragment : entry.at("message"))
    EXPECT_TRUE(contains(o.output, fragment.get<std::string>()))
        << "missing '" << fragment.get<std::string>() << "' in: " << o.output;
  EXPECT_EQ(o.output.rfind("hystbench: error: ", 0), 0u) << o.output;
  EXPECT_EQ(o.output.find('\n'), o.output.size() - 1) << "more than one line: " << o.output;
  EXPECT_FALSE(fs::exists(out)) << "output left in " << out;
  EXPECT_EQ(corpus_listing(), before) << "files were written into the corpus folder";
}

INSTANTIATE_TEST_SUITE_P(Corpus, RejectedInput, ::testing::ValuesIn(entries("rejected")), test_name);

class AcceptedInput : public ::testing::TestWithParam<Entry> {};

void expect_column(const Eigen::VectorXd& read, const nlohmann::json& expected, const char* name) {
  const auto values = expected.get<std::vector<double>>();
  ASSERT_EQ(read.size(), Eigen::Index(values.size())) << name;
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(read[i], values[i]) << name << "[" << i << "]";
}

TEST_P(AcceptedInput, IsReadWithTheListedValues) {
  const auto& entry = GetParam();
  auto columns = ColumnMap::parse(entry.json.value("columns", std::string("")));
  columns.delimiter = ColumnMap::parse_delimiter(entry.json.value("delimiter", std::string("auto")));
  const Measurement m = read_measurement(kCorpus / entry.at("file").get<std::string>(), columns);
  expect_column(m.t, entry.at("t"), "t");
  expect_column(m.u, entry.at("u"), "u");
  expect_column(m.y, entry.at("y"), "y");
  EXPECT_EQ(m.segment, entry.json.value("segment", std::vector<std::string>{}));
  EXPECT_EQ(m.u_unit, entry.json.value("u_unit", std::string()));
  EXPECT_EQ(m.y_unit, entry.json.value("y_unit", std::string()));
}

INSTANTIATE_TEST_SUITE_P(Corpus, AcceptedInput, ::testing::ValuesIn(entries("accepted")), test_name);

TEST(BadInputCorpus, HasAtLeastThirtyRejectedFilesEachListedOnce) {
  std::set<std::string> files;
  for (const auto& e : entries("rejected")) files.insert(e.at("file").get<std::string>());
  EXPECT_GE(files.size(), 30u);
  for (const auto& e : fs::directory_iterator(kCorpus)) {
    const auto name = e.path().filename().string();
    if (name == "manifest.json" || name.front() == '.') continue;
    bool listed = files.count(name) > 0;
    for (const auto& a : entries("accepted")) listed = listed || a.at("file") == name;
    // A data file an experiment of the corpus names is listed through it.
    for (const auto& f : files)
      listed = listed || (f.ends_with(".json") && test_support::contains(test_support::read(fs::path(kCorpus) / f), "\"" + name + "\""));
    EXPECT_TRUE(listed) << name << " is in the corpus but not in manifest.json";
  }
}

}  // namespace
}  // namespace hystbench
