// The documentation stays true to the code: docs/plugins.md shows the
// example plugins that the out-of-tree tests build and run, every page and
// heading that a source or a page cites as docs/<page>.md#<anchor> exists,
// and the README stays a front page.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/source_tree.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path& kRoot = hystbench::test_support::kSourceRoot;

std::string read(const fs::path& path) { return hystbench::test_support::read_file(path); }

// The section of a page that starts at `heading` ("\n## Title\n"), up to the
// next section of the same level; empty when the page has no such heading.
std::string section(const std::string& page, const std::string& heading) {
  const auto start = page.find(heading);
  if (start == std::string::npos) return {};
  return page.substr(start, page.find("\n## ", start + 1) - start);
}

std::string plugins_section(const std::string& heading) {
  return section(read(kRoot / "docs/plugins.md"), "\n## " + heading + "\n");
}

TEST(PluginsPage, AddAnOptimizerCodeIsTheTestedExamplePlugin) {
  std::string example = read(kRoot / "examples/random_search_plugin/random_search.cpp");
  ASSERT_FALSE(example.empty());
  example.erase(0, example.find('\n') + 1);  // its own one-line header comment
  const std::string text = plugins_section("Adding an optimizer");
  ASSERT_FALSE(text.empty()) << "docs/plugins.md has no section \"Adding an optimizer\"";
  EXPECT_NE(text.find(example), std::string::npos)
      << "docs/plugins.md's \"Adding an optimizer\" no longer shows "
         "examples/random_search_plugin/random_search.cpp";
}

TEST(PluginsPage, AddAnEffectCodeIsTheTestedExampleEffect) {
  const std::string example = read(kRoot / "examples/thermal_drift_effect/thermal_drift.cpp");
  ASSERT_FALSE(example.empty());
  const std::string text = plugins_section("Adding a physical effect");
  ASSERT_FALSE(text.empty()) << "docs/plugins.md has no section \"Adding a physical effect\"";
  EXPECT_NE(text.find(example), std::string::npos)
      << "docs/plugins.md's \"Adding a physical effect\" no longer shows "
         "examples/thermal_drift_effect/thermal_drift.cpp";
}

// The walkthrough's commands use the example's files: each one it names
// ($E/true.json, examples/thermal_drift_effect/..., E being that folder) is
// shipped, so the commands run as written.
TEST(PluginsPage, AddAnEffectNamesOnlyShippedExampleFiles) {
  const std::string text = plugins_section("Adding a physical effect");
  ASSERT_FALSE(text.empty());
  ASSERT_NE(text.find("E=examples/thermal_drift_effect\n"), std::string::npos);
  const std::regex named(R"((?:\$E/|examples/thermal_drift_effect/)([A-Za-z0-9_.]+))");
  std::set<std::string> files;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), named); it != std::sregex_iterator();
       ++it)
    files.insert((*it)[1]);
  for (const char* expected : {"true.json", "excitation.json"}) EXPECT_EQ(files.count(expected), 1u);
  for (const auto& f : files)
    EXPECT_TRUE(fs::is_regular_file(kRoot / "examples/thermal_drift_effect" / f))
        << "docs/plugins.md names examples/thermal_drift_effect/" << f << ", which is not shipped";
}

// The licence and the citation name the version being built.
TEST(Readme, LicenceAndCitationMatchTheBuild) {
  std::smatch version;
  const std::string cmake = read(kRoot / "CMakeLists.txt");
  ASSERT_TRUE(std::regex_search(cmake, version, std::regex(R"(project\(hystbench VERSION ([0-9.]+))")));
  const std::string v = version[1];
  EXPECT_NE(read(kRoot / "CITATION.cff").find("\nversion: " + v + "\n"), std::string::npos)
      << "CITATION.cff does not give version " << v;
  EXPECT_NE(read(kRoot / "CITATION.cff").find("license: BSD-3-Clause"), std::string::npos);
  EXPECT_NE(read(kRoot / "LICENSE").find("BSD 3-Clause License"), std::string::npos);
  const std::string readme = read(kRoot / "README.md");
  EXPECT_NE(readme.find("version = {" + v + "}"), std::string::npos)
      << "the README's BibTeX entry does not give version " << v;
}

TEST(Readme, IsAFrontPageOfAtMost300Lines) {
  const std::string readme = read(kRoot / "README.md");
  ASSERT_FALSE(readme.empty());
  EXPECT_LE(std::count(readme.begin(), readme.end(), '\n'), 300)
      << "README.md is the front page: move the details into a page of docs/";
}

// GitHub's anchor for a heading: lower case, backticks and punctuation
// dropped except '-' and '_', each space a '-'. Non-ASCII characters (the
// dashes of "Bouc–Wen", "∞") are dropped too: no heading has a non-ASCII
// letter.
std::string slug(const std::string& heading) {
  std::string anchor;
  for (const char ch : heading) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x80 && (std::isalnum(c) || c == '-' || c == '_'))
      anchor += static_cast<char>(std::tolower(c));
    else if (c == ' ')
      anchor += '-';
  }
  return anchor;
}

// The text of a Markdown heading line ("## Effect catalog"), or nothing.
std::optional<std::string> heading_text(const std::string& line) {
  static const std::regex heading(R"(#{1,6} +(.*\S)\s*)");
  std::smatch m;
  if (!std::regex_match(line, m, heading)) return std::nullopt;
  return m[1].str();
}

// Every anchor of a page: the slugs of its headings outside code fences, a
// repeated slug numbered as GitHub numbers it (name, name-1, name-2, ...).
std::set<std::string> anchors(const fs::path& page) {
  std::ifstream in(page);
  std::set<std::string> result;
  std::map<std::string, int> seen;
  bool fenced = false;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.starts_with("```")) fenced = !fenced;
    if (fenced) continue;
    const auto text = heading_text(line);
    if (!text) continue;
    const std::string base = slug(*text);
    const int n = seen[base]++;
    result.insert(n == 0 ? base : base + "-" + std::to_string(n));
  }
  return result;
}

TEST(DocCitations, AnchorsAreGitHubSlugs) {
  EXPECT_EQ(slug("`hystbench run`"), "hystbench-run");
  EXPECT_EQ(slug("Effect catalog"), "effect-catalog");
  EXPECT_EQ(slug("`hammerstein` — the MFC seed model"), "hammerstein--the-mfc-seed-model");
  EXPECT_EQ(slug("Running on a cluster (MPI)"), "running-on-a-cluster-mpi");
  EXPECT_EQ(slug("The seed's printed design"), "the-seeds-printed-design");
  EXPECT_EQ(slug("vss_fxlms"), "vss_fxlms");
  EXPECT_EQ(slug("L-SHADE"), "l-shade");
  EXPECT_EQ(heading_text("### `hystbench run`").value_or(""), "`hystbench run`");
  EXPECT_FALSE(heading_text("#include <cmath>").has_value());
}

TEST(DocCitations, RepeatedHeadingsAreNumberedAndCodeIsNoHeading) {
  const auto plugins = anchors(kRoot / "docs/plugins.md");
  EXPECT_EQ(plugins.count("in-the-tree-one-file"), 1u);
  EXPECT_EQ(plugins.count("in-the-tree-one-file-1"), 1u);
  const auto cluster = anchors(kRoot / "docs/cluster.md");
  EXPECT_EQ(cluster.count("slurm"), 1u);
  EXPECT_EQ(cluster.count("or-where-srun-has-no-mpi-support"), 0u);  // a comment in a script
}

struct Citation {
  std::string page;    // docs/<page>.md
  std::string anchor;  // empty when the citation names the page only
};

bool is_name_char(char ch, bool dot) {
  const auto c = static_cast<unsigned char>(ch);
  return c < 0x80 && (std::isalnum(c) || c == '_' || c == '-' || (dot && c == '.'));
}

// The citation that starts at text[at] ("docs/..."), if one does.
std::optional<Citation> citation_at(const std::string& text, std::size_t at) {
  auto end = at + 5;
  while (end < text.size() && is_name_char(text[end], true)) ++end;
  const std::string name = text.substr(at + 5, end - at - 5);
  const auto md = name.rfind(".md");
  if (md == std::string::npos || md == 0) return std::nullopt;
  Citation c{"docs/" + name.substr(0, md + 3), ""};
  if (md + 3 != name.size() || end >= text.size() || text[end] != '#') return c;
  while (++end < text.size() && is_name_char(text[end], false)) c.anchor += text[end];
  return c;
}

// Every docs/<page>.md and docs/<page>.md#<anchor> in a file.
std::vector<Citation> citations_in(const fs::path& file) {
  const std::string text = read(file);
  std::vector<Citation> found;
  for (auto at = text.find("docs/"); at != std::string::npos; at = text.find("docs/", at + 1))
    if (const auto c = citation_at(text, at)) found.push_back(*c);
  return found;
}

bool is_scanned(const fs::path& file) {
  static const std::set<std::string> extensions = {".md",    ".cpp", ".hpp", ".h",  ".sh",
                                                   ".json",  ".txt", ".in",  ".py", ".cmake"};
  return extensions.count(file.extension().string()) > 0 || file.filename() == "Makefile";
}

// The files whose citations are checked: sources, scripts and pages, without
// build folders.
std::vector<fs::path> scanned_files() {
  std::vector<fs::path> files = {kRoot / "README.md", kRoot / "CMakeLists.txt", kRoot / "Makefile"};
  for (const char* top : {"framework", "problems", "plugins", "benchmarks", "tests", "examples",
                          "docs", "results", "scripts", "fuzz", "cmake"}) {
    if (!fs::is_directory(kRoot / top)) continue;
    for (auto it = fs::recursive_directory_iterator(kRoot / top);
         it != fs::recursive_directory_iterator(); ++it) {
      if (it->is_directory() && it->path().filename().string().starts_with("build"))
        it.disable_recursion_pending();
      else if (it->is_regular_file() && is_scanned(it->path()))
        files.push_back(it->path());
    }
  }
  return files;
}

// What is wrong with a citation, or "" when its page and heading exist.
std::string broken(const Citation& c, std::map<std::string, std::set<std::string>>& anchors_of) {
  const fs::path page = kRoot / c.page;
  if (!fs::is_regular_file(page)) return c.page + " does not exist";
  if (c.anchor.empty()) return "";
  auto [it, added] = anchors_of.try_emplace(c.page);
  if (added) it->second = anchors(page);
  return it->second.count(c.anchor) > 0 ? "" : c.page + " has no heading #" + c.anchor;
}

TEST(DocCitations, EveryCitedPageAndHeadingExists) {
  std::map<std::string, std::set<std::string>> anchors_of;
  int checked = 0;
  for (const auto& file : scanned_files())
    for (const auto& c : citations_in(file)) {
      ++checked;
      const std::string problem = broken(c, anchors_of);
      EXPECT_EQ(problem, "") << file.lexically_relative(kRoot).string() << " cites " << c.page
                             << (c.anchor.empty() ? "" : "#" + c.anchor);
    }
  EXPECT_GT(checked, 100) << "the scan found too few citations to be looking in the right place";
}

}  // namespace
