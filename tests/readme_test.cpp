// The README's "Adding an optimizer" and "Adding a physical effect" code is
// the example plugins that the out-of-tree tests build and run, so the
// walkthroughs stay true.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Readme, AddAnOptimizerCodeIsTheTestedExamplePlugin) {
  const std::string root = HYSTBENCH_SOURCE_DIR;
  std::string example = read(root + "/examples/random_search_plugin/random_search.cpp");
  ASSERT_FALSE(example.empty());
  example.erase(0, example.find('\n') + 1);  // its own one-line header comment
  EXPECT_NE(read(root + "/README.md").find(example), std::string::npos)
      << "README.md no longer shows examples/random_search_plugin/random_search.cpp";
}

TEST(Readme, AddAnEffectCodeIsTheTestedExampleEffect) {
  const std::string root = HYSTBENCH_SOURCE_DIR;
  const std::string example = read(root + "/examples/thermal_drift_effect/thermal_drift.cpp");
  ASSERT_FALSE(example.empty());
  const std::string readme = read(root + "/README.md");
  const auto section = readme.find("\n## Adding a physical effect\n");
  ASSERT_NE(section, std::string::npos) << "README.md has no section \"Adding a physical effect\"";
  const auto next = readme.find("\n## ", section + 1);
  EXPECT_NE(readme.substr(section, next - section).find(example), std::string::npos)
      << "README.md's \"Adding a physical effect\" no longer shows "
         "examples/thermal_drift_effect/thermal_drift.cpp";
}

// The walkthrough's commands use the example's files: each one it names
// ($E/true.json, examples/thermal_drift_effect/..., E being that folder) is
// shipped, so the commands run as written.
TEST(Readme, AddAnEffectNamesOnlyShippedExampleFiles) {
  const std::string root = HYSTBENCH_SOURCE_DIR;
  const std::string readme = read(root + "/README.md");
  const auto section = readme.find("\n## Adding a physical effect\n");
  ASSERT_NE(section, std::string::npos);
  const std::string text = readme.substr(section, readme.find("\n## ", section + 1) - section);
  ASSERT_NE(text.find("E=examples/thermal_drift_effect\n"), std::string::npos);
  const std::regex named(R"((?:\$E/|examples/thermal_drift_effect/)([A-Za-z0-9_.]+))");
  std::set<std::string> files;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), named); it != std::sregex_iterator();
       ++it)
    files.insert((*it)[1]);
  for (const char* expected : {"true.json", "excitation.json"}) EXPECT_EQ(files.count(expected), 1u);
  for (const auto& f : files)
    EXPECT_TRUE(std::filesystem::is_regular_file(root + "/examples/thermal_drift_effect/" + f))
        << "README.md names examples/thermal_drift_effect/" << f << ", which is not shipped";
}

}  // namespace
