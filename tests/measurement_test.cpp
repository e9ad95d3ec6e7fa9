#include "framework/io/measurement.hpp"

#include <gtest/gtest.h>

#include "tests/temp_dir.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "framework/core/error.hpp"

namespace fs = std::filesystem;
using hystbench::ColumnMap;
using hystbench::InputError;
using hystbench::Measurement;
using hystbench::read_measurement;
using hystbench::write_measurement;

namespace {

using hystbench::test_support::TempDir;

// The message of the InputError that reading `p` throws; fails the test if none.
std::string read_error(const fs::path& p, const ColumnMap& columns = {}) {
  try {
    read_measurement(p, columns);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "reading " << p << " did not throw InputError";
  return {};
}

std::string parse_error(const std::string& spec) {
  try {
    ColumnMap::parse(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parsing '" << spec << "' did not throw InputError";
  return {};
}

std::string json_error(const nlohmann::json& j, const std::string& where) {
  try {
    ColumnMap::from_json(j, where);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "from_json(" << j.dump() << ") did not throw InputError";
  return {};
}

// Substring checks with the whole message shown on failure.
#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

const std::string kPlain = "t,u,y\n0,1,10\n0.5,2,20\n1,3,30\n";

void expect_plain(const Measurement& m) {
  ASSERT_EQ(m.size(), 3);
  EXPECT_EQ(m.t[0], 0.0);
  EXPECT_EQ(m.t[2], 1.0);
  EXPECT_EQ(m.u[1], 2.0);
  EXPECT_EQ(m.y[2], 30.0);
  EXPECT_DOUBLE_EQ(m.sample_time, 0.5);
}

}  // namespace

// ---- accepted files ------------------------------------------------------

TEST(Measurement, ReadsPlainFile) {
  TempDir dir;
  const auto p = dir.write("plain.csv", kPlain);
  const Measurement m = read_measurement(p);
  expect_plain(m);
  EXPECT_TRUE(m.segment.empty());
  EXPECT_EQ(m.source, p.string());
}

TEST(Measurement, ColumnsInAnyOrderAndExtraColumnsIgnored) {
  TempDir dir;
  const auto p = dir.write("order.csv",
                           "note,y,extra,t,u\n"
                           "a,10,x,0,1\n"
                           "b,20,,0.5,2\n"
                           "c,30,not a number,1,3\n");
  expect_plain(read_measurement(p));
}

TEST(Measurement, AcceptsBomAndCrlf) {
  TempDir dir;
  const auto p = dir.write("bom.csv", "\xEF\xBB\xBFt,u,y\r\n0,1,10\r\n0.5,2,20\r\n1,3,30\r\n");
  expect_plain(read_measurement(p));
}

TEST(Measurement, AcceptsQuotedFieldsAndHeader) {
  TempDir dir;
  const auto p = dir.write("quoted.csv",
                           "\"t\",\"u\",\"y\",\"segment\"\n"
                           "\"0\",1,\"10\",\"a, \"\"quoted\"\" label\"\n"
                           "0.5, \"2\" ,20,plain\n"
                           "1,3,30,\"\"\n");
  const Measurement m = read_measurement(p);
  expect_plain(m);
  ASSERT_EQ(m.segment.size(), 3u);
  EXPECT_EQ(m.segment[0], "a, \"quoted\" label");
  EXPECT_EQ(m.segment[1], "plain");
  EXPECT_EQ(m.segment[2], "");
}

TEST(Measurement, SkipsCommentsAndBlankLines) {
  TempDir dir;
  const auto p = dir.write("comments.csv",
                           "# recorded on the test rig\n"
                           "\n"
                           "   # indented comment\n"
                           "t,u,y\n"
                           "0,1,10\n"
                           "# a comment between rows, with, commas\n"
                           "   \t\n"
                           "0.5,2,20\n"
                           "1,3,30\n"
                           "# trailing comment\n");
  expect_plain(read_measurement(p));
}

TEST(Measurement, AcceptsMissingTrailingNewlineAndBlanksAroundFields) {
  TempDir dir;
  const auto p = dir.write("blanks.csv", " t , u ,\ty\n 0 ,\t1, 10 \n0.5,+2,2e1\n1,3,30");
  expect_plain(read_measurement(p));
}

TEST(Measurement, ReadsSegmentColumn) {
  TempDir dir;
  const auto p = dir.write("seg.csv", "t,segment,u,y\n0,train,1,10\n0.5,train,2,20\n1,test,3,30\n");
  const Measurement m = read_measurement(p);
  expect_plain(m);
  EXPECT_EQ(m.segment, (std::vector<std::string>{"train", "train", "test"}));
}

TEST(Measurement, AppliesColumnMap) {
  TempDir dir;
  const auto p = dir.write("mapped.csv",
                           "t_s,u_N,y_m,phase,t\n0,1,10,a,7\n0.5,2,20,a,8\n1,3,30,b,9\n");
  const Measurement m = read_measurement(p, ColumnMap::parse("t=t_s,u=u_N,y=y_m,segment=phase"));
  expect_plain(m);
  EXPECT_EQ(m.segment, (std::vector<std::string>{"a", "a", "b"}));
}

TEST(Measurement, AcceptsTimesOfAnIrrationalStep) {
  // k/750 written with 17 digits and rounded to 9 significant digits: both
  // are evenly sampled within what their precision can express.
  TempDir dir;
  std::string full = "t,u,y\n", rounded = "t,u,y\n";
  char buf[64];
  for (int k = 0; k < 5000; ++k) {
    std::snprintf(buf, sizeof buf, "%.17g,%d,0\n", k / 750.0, k);
    full += buf;
    std::snprintf(buf, sizeof buf, "%.9g,%d,0\n", k / 750.0, k);
    rounded += buf;
  }
  const Measurement exact = read_measurement(dir.write("full.csv", full));
  EXPECT_EQ(exact.size(), 5000);
  EXPECT_NEAR(exact.sample_time, 1.0 / 750, 1e-17);
  const Measurement coarse = read_measurement(dir.write("rounded.csv", rounded));
  EXPECT_EQ(coarse.size(), 5000);
  EXPECT_NEAR(coarse.sample_time, 1.0 / 750, 1e-11);
}

// ---- rejected files ------------------------------------------------------

TEST(Measurement, RejectsMissingFile) {
  TempDir dir;
  const std::string msg = read_error(dir.path() / "nowhere.csv");
  EXPECT_CONTAINS(msg, "nowhere.csv");
  EXPECT_CONTAINS(msg, "not found");
}

TEST(Measurement, RejectsFolder) {
  TempDir dir;
  fs::create_directory(dir.path() / "folder.csv");
  EXPECT_CONTAINS(read_error(dir.path() / "folder.csv"), "folder.csv");
}

TEST(Measurement, RejectsEmptyFile) {
  TempDir dir;
  for (const std::string text : {"", "\xEF\xBB\xBF", "\n\n", "# only a comment\n"}) {
    const std::string msg = read_error(dir.write("empty.csv", text));
    EXPECT_CONTAINS(msg, "empty.csv");
    EXPECT_CONTAINS(msg, "empty");
  }
}

TEST(Measurement, RejectsHeaderOnly) {
  TempDir dir;
  const std::string msg = read_error(dir.write("header.csv", "# c\nt,u,y\n# c\n"));
  EXPECT_CONTAINS(msg, "header.csv");
  EXPECT_CONTAINS(msg, "line 2");
  EXPECT_CONTAINS(msg, "no data rows");
}

TEST(Measurement, RejectsSingleSample) {
  TempDir dir;
  const std::string msg = read_error(dir.write("one.csv", "t,u,y\n0,1,2\n"));
  EXPECT_CONTAINS(msg, "one.csv");
  EXPECT_CONTAINS(msg, "line 2");
  EXPECT_CONTAINS(msg, "two");
}

TEST(Measurement, RejectsMissingColumnListingHeaderAndOption) {
  TempDir dir;
  const auto p = dir.write("names.csv", "ch0_s,ch1_N,ch2_m\n0,1,2\n1,2,3\n");
  const std::string msg = read_error(p);
  EXPECT_CONTAINS(msg, "names.csv");
  EXPECT_CONTAINS(msg, "line 1");
  EXPECT_CONTAINS(msg, "'t'");
  EXPECT_CONTAINS(msg, "'ch0_s', 'ch1_N', 'ch2_m'");
  EXPECT_CONTAINS(msg, "--columns t=ch0_s,u=ch1_N,y=ch2_m");
  // Names with their units, as a DAQ program writes them, need no option.
  const Measurement m = read_measurement(dir.write("units.csv", "t_s,u_N,y_m\n0,1,2\n1,2,3\n"));
  EXPECT_EQ(m.y[1], 3.0);
  EXPECT_EQ(m.u_unit, "N");
  EXPECT_EQ(m.y_unit, "m");
}

TEST(Measurement, RejectsMissingMappedColumn) {
  TempDir dir;
  const auto p = dir.write("mapped.csv", "# c\nt,u,y\n0,1,2\n1,2,3\n");
  const std::string msg = read_error(p, ColumnMap::parse("y=y_m"));
  EXPECT_CONTAINS(msg, "mapped.csv");
  EXPECT_CONTAINS(msg, "line 2");
  EXPECT_CONTAINS(msg, "'y_m'");
  EXPECT_CONTAINS(msg, "--columns");
}

TEST(Measurement, RejectsDuplicateColumn) {
  TempDir dir;
  const std::string msg = read_error(dir.write("dup.csv", "t,u,y,\"u\"\n0,1,2,3\n1,2,3,4\n"));
  EXPECT_CONTAINS(msg, "dup.csv");
  EXPECT_CONTAINS(msg, "line 1");
  EXPECT_CONTAINS(msg, "column 'u'");
  EXPECT_CONTAINS(msg, "twice");
}

TEST(Measurement, RejectsBadNumbers) {
  TempDir dir;
  const struct {
    std::string value;
    std::string says;
  } cases[] = {{"abc", "not a number"}, {"1.5x", "not a number"}, {"NaN", "not a finite"},
               {"nan", "not a finite"}, {"inf", "not a finite"}, {"-Infinity", "not a finite"},
               {"", "empty"},           {"\"\"", "empty"},       {"1e999", "out of the range"}};
  for (const auto& c : cases) {
    const auto p =
        dir.write("bad.csv", "t,u_N,y\n# comment\n0,1,2\n0.5," + c.value + ",3\n1,1,1\n");
    const std::string msg = read_error(p, ColumnMap::parse("u=u_N"));
    EXPECT_CONTAINS(msg, "bad.csv") << c.value;
    EXPECT_CONTAINS(msg, "line 4") << c.value;
    EXPECT_CONTAINS(msg, "column 'u_N'") << c.value;
    EXPECT_CONTAINS(msg, c.says) << c.value;
  }
}

TEST(Measurement, RejectsRaggedRows) {
  TempDir dir;
  for (const std::string row : {"0.5,2", "0.5,2,20,99"}) {
    const std::string msg =
        read_error(dir.write("ragged.csv", "t,u,y\n0,1,10\n\n" + row + "\n1,3,30\n"));
    EXPECT_CONTAINS(msg, "ragged.csv");
    EXPECT_CONTAINS(msg, "line 4");
    EXPECT_CONTAINS(msg, "header (line 1) has 3");
  }
}

// A spreadsheet in a locale with decimal commas saves ';' between fields:
// read as it is, and refused with a way out when a comma is forced.
TEST(Measurement, ReadsSemicolonDelimiterWithDecimalCommas) {
  TempDir dir;
  const auto p = dir.write("semi.csv", "# exported\nt;u;y\n0;1,5;10\n0,5;2;20\n");
  const Measurement m = read_measurement(p);
  EXPECT_EQ(m.u[0], 1.5);
  EXPECT_EQ(m.t[1], 0.5);
  ColumnMap comma;
  comma.delimiter = ',';
  const std::string msg = read_error(p, comma);
  EXPECT_TRUE(msg.ends_with(
      "/semi.csv, line 2: the header 't;u;y' is one field with --delimiter comma; it seems to use "
      "another delimiter: leave --delimiter out (auto) or give the one the file uses (comma, "
      "semicolon or tab)"))
      << msg;
}

// Decimal commas in a comma-separated file split each number in two.
TEST(Measurement, RejectsDecimalCommasNamingThem) {
  TempDir dir;
  const std::string msg =
      read_error(dir.write("commas.csv", "t,u,y\n0,1,10\n0,5,2,20\n1,3,30\n"));
  EXPECT_TRUE(msg.ends_with(
      "/commas.csv, line 3: the row has 4 fields but the header (line 1) has 3, and no decimal "
      "point: the file seems to use decimal commas; a file with commas between fields needs "
      "decimal points (1.5, not 1,5); decimal commas are read in files with ';' or tabs between "
      "fields. Write the numbers with '.' instead"))
      << msg;
  // Quoted, a decimal comma stays in one field, which is then not a number.
  const std::string quoted =
      read_error(dir.write("quoted.csv", "t,u,y\n0,1,10\n0.5,\"-2,25\",20\n1,3,30\n"));
  EXPECT_CONTAINS(quoted, "quoted.csv, line 3: column 'u': '-2,25' is not a number: it seems to be "
                          "written with a decimal comma");
  // A row with a decimal point and one field too many is an ordinary ragged row.
  const std::string ragged = read_error(dir.write("ragged.csv", "t,u,y\n0,1,10\n0.5,2,20,1\n"));
  EXPECT_CONTAINS(ragged, "check for a missing or extra comma");
  EXPECT_EQ(ragged.find("decimal"), std::string::npos) << ragged;
}

TEST(Measurement, RejectsUnterminatedQuote) {
  TempDir dir;
  const std::string msg = read_error(dir.write("quote.csv", "t,u,y\n0,\"1,10\n0.5,2,20\n"));
  EXPECT_CONTAINS(msg, "quote.csv");
  EXPECT_CONTAINS(msg, "line 2");
  EXPECT_CONTAINS(msg, "closing");
}

TEST(Measurement, RejectsTimeNotIncreasing) {
  TempDir dir;
  for (const std::string t : {"0.5", "0.25"}) {
    const auto p =
        dir.write("order.csv", "time,u,y\r\n0,1,1\r\n0.5,1,1\r\n# c\r\n" + t + ",1,1\r\n");
    const std::string msg = read_error(p, ColumnMap::parse("t=time"));
    EXPECT_CONTAINS(msg, "order.csv");
    EXPECT_CONTAINS(msg, "line 5");
    EXPECT_CONTAINS(msg, "column 'time'");
    EXPECT_CONTAINS(msg, "strictly increase");
  }
}

TEST(Measurement, RejectsUnevenSteps) {
  TempDir dir;
  // A missing sample shifts the mean step; the message must still point at
  // the gap (line 5), not at the first row.
  const std::string gap = read_error(
      dir.write("gap.csv", "t,u,y\n0,1,1\n0.1,1,1\n0.2,1,1\n0.4,1,1\n0.5,1,1\n0.6,1,1\n"));
  EXPECT_CONTAINS(gap, "gap.csv");
  EXPECT_CONTAINS(gap, "line 5");
  EXPECT_CONTAINS(gap, "column 't'");
  EXPECT_CONTAINS(gap, "evenly spaced");

  // Jitter of 1e-4 of a step, in times written with 10 digits: far below a
  // step, far above what 10-digit rounding explains.
  const std::string jitter = read_error(
      dir.write("jitter.csv",
                "t,u,y\n0,1,1\n0.1,1,1\n0.2,1,1\n0.3000100000,1,1\n0.4,1,1\n0.5,1,1\n"));
  EXPECT_CONTAINS(jitter, "jitter.csv");
  EXPECT_TRUE(jitter.find("line 5") != std::string::npos ||
              jitter.find("line 6") != std::string::npos)
      << jitter;
  EXPECT_CONTAINS(jitter, "evenly spaced");
}

// ---- column maps ---------------------------------------------------------

TEST(Measurement, ColumnMapParse) {
  const ColumnMap full = ColumnMap::parse("t=t_s,u=u_N,y=y_m");
  EXPECT_EQ(full.t, "t_s");
  EXPECT_EQ(full.u, "u_N");
  EXPECT_EQ(full.y, "y_m");
  EXPECT_EQ(full.segment, "segment");

  const ColumnMap some = ColumnMap::parse(" segment = phase , y=out ");
  EXPECT_EQ(some.t, "t");
  EXPECT_EQ(some.u, "u");
  EXPECT_EQ(some.y, "out");
  EXPECT_EQ(some.segment, "phase");
}

TEST(Measurement, ColumnMapParseRejectsBadEntries) {
  for (const std::string spec : {"x=foo", "t=a,x=foo"}) {
    const std::string msg = parse_error(spec);
    EXPECT_CONTAINS(msg, "'x=foo'");
    EXPECT_CONTAINS(msg, "t, u, y, segment");
  }
  for (const std::string spec : {"t", "t=", "u=a,,y=b"}) {
    const std::string msg = parse_error(spec);
    EXPECT_CONTAINS(msg, "role=name");
    EXPECT_CONTAINS(msg, "t, u, y, segment");
  }
  EXPECT_CONTAINS(parse_error("t=a,t=b"), "twice");
}

TEST(Measurement, ColumnMapJson) {
  const ColumnMap map =
      ColumnMap::from_json({{"t", "t_s"}, {"u", "u_N"}, {"y", "y_m"}}, "data.columns");
  EXPECT_EQ(map.t, "t_s");
  EXPECT_EQ(map.u, "u_N");
  EXPECT_EQ(map.y, "y_m");
  EXPECT_EQ(map.segment, "segment");
  EXPECT_EQ(map.to_json(),
            (nlohmann::json{{"t", "t_s"}, {"u", "u_N"}, {"y", "y_m"}, {"segment", "segment"}}));

  const std::string unknown = json_error({{"t", "a"}, {"x", "foo"}}, "data.columns");
  EXPECT_CONTAINS(unknown, "data.columns.x");
  EXPECT_CONTAINS(unknown, "t, u, y, segment");
  EXPECT_CONTAINS(json_error({{"u", 5}}, "data.columns"), "data.columns.u");
  EXPECT_CONTAINS(json_error(nlohmann::json::array(), "data.columns"), "data.columns");
}

// ---- writing -------------------------------------------------------------

TEST(Measurement, RoundTripIsBitIdentical) {
  TempDir dir;
  Measurement m;
  const int n = 200;
  m.t.resize(n);
  m.u.resize(n);
  m.y.resize(n);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (int i = 0; i < n; ++i) {
    m.t[i] = i / 750.0;
    m.u[i] = normal(rng) * std::pow(10.0, (i % 40) - 20);
    m.y[i] = normal(rng);
    m.segment.push_back(i % 3 == 0 ? "train" : "a, \"quoted\" label ");
  }
  m.u[1] = -0.0;
  m.u[2] = std::numeric_limits<double>::denorm_min();
  m.u[3] = 1e150;  // the largest magnitude read: squares of larger ones overflow the SSE
  m.y[4] = -std::numeric_limits<double>::min();

  const auto p = dir.path() / "round.csv";
  write_measurement(p, m, {"first comment", "second\nand third"});
  const Measurement back = read_measurement(p);
  ASSERT_EQ(back.size(), n);
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(same_bits(back.t[i], m.t[i])) << i;
    EXPECT_TRUE(same_bits(back.u[i], m.u[i])) << i;
    EXPECT_TRUE(same_bits(back.y[i], m.y[i])) << i;
  }
  EXPECT_EQ(back.segment, m.segment);
  EXPECT_NEAR(back.sample_time, 1.0 / 750, 1e-15);
}

TEST(Measurement, WritesHeaderCommentsAndNoTempFile) {
  TempDir dir;
  Measurement m;
  m.t = Eigen::Vector2d(0.0, 0.1);
  m.u = Eigen::Vector2d(1.0, 2.0);
  m.y = Eigen::Vector2d(3.0, 4.0);
  const auto p = dir.path() / "plain.csv";
  write_measurement(p, m, {"made by a test"});
  std::ifstream in(p, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(text, "# made by a test\nt,u,y\n0,1,3\n0.10000000000000001,2,4\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

