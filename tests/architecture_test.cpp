// The layers docs/architecture.md lists are the ones the code keeps: every
// #include of framework/, problems/ and plugins/ points at its own layer or
// one above it in that list.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/source_tree.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path& kRoot = hystbench::test_support::kSourceRoot;

std::string read(const fs::path& path) { return hystbench::test_support::read_file(path); }

// The folders of the "## Layers" code block, top (lowest layer) first;
// "plugins/<name>/" stands for every optimizer plugin folder.
std::vector<std::string> documented_layers() {
  const std::string page = read(kRoot / "docs/architecture.md");
  const auto start = page.find("```\n", page.find("\n## Layers\n"));
  const auto end = page.find("```", start + 4);
  std::istringstream block(page.substr(start + 4, end - start - 4));
  std::vector<std::string> layers;
  for (std::string line; std::getline(block, line);) {
    std::string folder = line.substr(0, line.find(' '));
    if (folder.ends_with('/')) folder.pop_back();
    if (folder == "plugins/<name>") folder = "plugins";
    if (!folder.empty()) layers.push_back(folder);
  }
  return layers;
}

// The layer of a repository path: the longest listed folder it is in.
int layer_of(const std::vector<std::string>& layers, const std::string& path) {
  int best = -1;
  for (int i = 0; i < int(layers.size()); ++i)
    if (path.starts_with(layers[i] + "/") && (best < 0 || layers[i].size() > layers[best].size()))
      best = i;
  return best;
}

TEST(Architecture, TheLayersPageListsTheFolders) {
  const auto layers = documented_layers();
  ASSERT_GE(layers.size(), 15u);
  for (const auto& folder : layers) EXPECT_TRUE(fs::is_directory(kRoot / folder)) << folder;
}

TEST(Architecture, NoFolderIncludesALayerBelowIt) {
  const auto layers = documented_layers();
  const std::regex include(R"(#include "([^"]+)\")");
  int checked = 0;
  for (const char* top : {"framework", "problems", "plugins"})
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / top)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp") continue;
      const std::string file = fs::relative(entry.path(), kRoot).generic_string();
      const int own = layer_of(layers, file);
      ASSERT_GE(own, 0) << file << " is in no layer of docs/architecture.md";
      const std::string text = read(entry.path());
      for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
        const int used = layer_of(layers, (*it)[1]);
        EXPECT_LE(used, own) << file << " includes " << (*it)[1] << ", a layer below its own";
        ++checked;
      }
    }
  EXPECT_GT(checked, 500);
}

}  // namespace
