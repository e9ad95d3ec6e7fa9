// The README's "Add an optimizer" code is the example plugin that the
// out-of-tree test builds and runs, so the walkthrough stays true.
#include <gtest/gtest.h>

#include <fstream>
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

}  // namespace
