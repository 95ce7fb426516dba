#include "sinew/io/csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "io_test_support.hpp"
#include "sinew/core/error.hpp"

namespace sinew::io {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::TempDir;

/// Splits CSV text into records of fields (RFC 4180: quoted fields may hold commas, doubled
/// quotes and line breaks).
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      record.push_back(field);
      field.clear();
    } else if (c == '\n') {
      record.push_back(field);
      field.clear();
      records.push_back(record);
      record.clear();
    } else {
      field += c;
    }
  }
  EXPECT_FALSE(quoted) << "unterminated quoted field";
  EXPECT_TRUE(record.empty() && field.empty()) << "last line does not end with a newline";
  return records;
}

TEST(Csv, HeaderIsWrittenWithTheFirstFlush) {
  TempDir scratch;
  CsvTable table(scratch.file("log/steps.csv"), {"step", "time", "note"});
  EXPECT_EQ(table.columns(), (std::vector<std::string>{"step", "time", "note"}));
  EXPECT_EQ(table.rows(), 0u);
  table.flush();
  EXPECT_EQ(read_text(table.path()), "step,time,note\n");
}

TEST(Csv, EachAddRowRewritesTheWholeFile) {
  TempDir scratch;
  CsvTable table(scratch.file("steps.csv"), {"step", "time", "status"});
  table.add_row({1LL, 0.5, std::string("ok")});
  EXPECT_EQ(read_text(table.path()), "step,time,status\n1,0.5,ok\n");
  table.add_row({2LL, 1.0, std::string("cut back")});
  EXPECT_EQ(read_text(table.path()), "step,time,status\n1,0.5,ok\n2,1,cut back\n");
  EXPECT_EQ(table.rows(), 2u);
}

TEST(Csv, AppendWritesOnlyOnFlush) {
  TempDir scratch;
  CsvTable table(scratch.file("contacts.csv"), {"pair", "force"});
  table.append({0LL, 1.5});
  table.append({1LL, -2.5});
  EXPECT_FALSE(fs::exists(table.path()));
  table.flush();
  EXPECT_EQ(read_text(table.path()), "pair,force\n0,1.5\n1,-2.5\n");
}

TEST(Csv, IntegersArePlain) {
  TempDir scratch;
  CsvTable table(scratch.file("ints.csv"), {"n"});
  table.add_row({0LL});
  table.add_row({-42LL});
  table.add_row({std::numeric_limits<long long>::max()});
  table.add_row({std::numeric_limits<long long>::min()});
  EXPECT_EQ(read_text(table.path()),
            "n\n0\n-42\n9223372036854775807\n-9223372036854775808\n");
}

TEST(Csv, StringsAreQuotedOnlyWhenNeeded) {
  TempDir scratch;
  const std::vector<std::string> texts = {
      "plain", "with space", "a,b", "say \"hi\"", "two\nlines", "cr\rhere", "", "\"", "'single'"};
  CsvTable table(scratch.file("strings.csv"), {"text", "header, with comma"});
  for (const std::string& text : texts) table.add_row({text, 0LL});
  const std::string content = read_text(table.path());
  EXPECT_EQ(content.substr(0, content.find('\n')), "text,\"header, with comma\"");
  EXPECT_NE(content.find("\nplain,0\n"), std::string::npos);
  EXPECT_NE(content.find("\nwith space,0\n"), std::string::npos);
  EXPECT_NE(content.find("\n\"a,b\",0\n"), std::string::npos);
  EXPECT_NE(content.find("\n\"say \"\"hi\"\"\",0\n"), std::string::npos);
  EXPECT_NE(content.find("\n\"two\nlines\",0\n"), std::string::npos);
  EXPECT_NE(content.find("\n\"\"\"\",0\n"), std::string::npos);
  EXPECT_NE(content.find("\n'single',0\n"), std::string::npos);

  const auto records = parse_csv(content);
  ASSERT_EQ(records.size(), texts.size() + 1);
  EXPECT_EQ(records[0], (std::vector<std::string>{"text", "header, with comma"}));
  for (std::size_t i = 0; i < texts.size(); ++i) {
    EXPECT_EQ(records[i + 1], (std::vector<std::string>{texts[i], "0"}));
  }
}

TEST(Csv, DoublesReadBackExactly) {
  const std::vector<double> values = {0.1,
                                      1.0 / 3.0,
                                      -2.0 / 7.0,
                                      0.1 + 0.2,
                                      6.02214076e23,
                                      1e-300,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::lowest(),
                                      std::numeric_limits<double>::epsilon(),
                                      -0.0,
                                      std::nextafter(1.0, 2.0),
                                      123456789.123456789};
  TempDir scratch;
  CsvTable table(scratch.file("doubles.csv"), {"value"});
  for (const double value : values) table.add_row({value});
  const auto records = parse_csv(read_text(table.path()));
  ASSERT_EQ(records.size(), values.size() + 1);
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_EQ(records[i + 1].size(), 1u);
    const double read_back = std::strtod(records[i + 1][0].c_str(), nullptr);
    EXPECT_EQ(std::memcmp(&read_back, &values[i], sizeof(double)), 0)
        << records[i + 1][0] << " does not read back as " << values[i];
  }
}

TEST(Csv, NonFiniteDoublesAreWrittenAsStrtodReadsThem) {
  TempDir scratch;
  CsvTable table(scratch.file("nonfinite.csv"), {"a", "b", "c"});
  table.add_row({std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                 -std::numeric_limits<double>::infinity()});
  const auto records = parse_csv(read_text(table.path()));
  ASSERT_EQ(records.size(), 2u);
  EXPECT_TRUE(std::isnan(std::strtod(records[1][0].c_str(), nullptr)));
  EXPECT_EQ(std::strtod(records[1][1].c_str(), nullptr), std::numeric_limits<double>::infinity());
  EXPECT_EQ(std::strtod(records[1][2].c_str(), nullptr), -std::numeric_limits<double>::infinity());
}

TEST(Csv, WrongRowLengthThrowsAndKeepsTheTable) {
  TempDir scratch;
  CsvTable table(scratch.file("steps.csv"), {"step", "time"});
  table.add_row({1LL, 0.5});
  try {
    table.add_row({2LL});
    FAIL() << "expected sinew::Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(table.path()), std::string::npos) << message;
    EXPECT_NE(message.find("1 cells, expected 2"), std::string::npos) << message;
  }
  EXPECT_THROW(table.append({2LL, 1.0, std::string("extra")}), Error);
  EXPECT_EQ(table.rows(), 1u);
  EXPECT_EQ(read_text(table.path()), "step,time\n1,0.5\n");
}

TEST(Csv, NoColumnsOrDuplicateColumnsAreErrors) {
  TempDir scratch;
  EXPECT_THROW(CsvTable(scratch.file("a.csv"), {}), Error);
  EXPECT_THROW(CsvTable(scratch.file("b.csv"), {"x", "y", "x"}), Error);
}

TEST(Csv, UnwritablePathThrowsNamingIt) {
  TempDir scratch;
  const std::string directory_in_the_way = scratch.file("table.csv");
  fs::create_directories(directory_in_the_way + "/inside");
  CsvTable table(directory_in_the_way, {"x"});
  try {
    table.add_row({1.0});
    FAIL() << "expected sinew::Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(directory_in_the_way), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sinew::io

namespace sinew::io {
namespace {

TEST(Csv, RestoreKeepsTheCountedRowsOfTheFileAndDropsLaterOnes) {
  TempDir scratch;
  const std::string path = scratch.file("steps.csv");
  {
    CsvTable table(path, {"step", "lambda"});
    for (long long k = 1; k <= 5; ++k) table.add_row({k, 0.1 * static_cast<double>(k)});
  }
  CsvTable resumed(path, {"step", "lambda"});
  resumed.restore(3);
  EXPECT_EQ(resumed.rows(), 3u);
  resumed.add_row({4LL, 0.4});
  EXPECT_EQ(read_text(path), "step,lambda\n1,0.10000000000000001\n2,0.20000000000000001\n3,0.30000000000000004\n"
                             "4,0.40000000000000002\n");
}

TEST(Csv, RestoreRefusesAMissingFileOtherColumnsAndTooFewRows) {
  TempDir scratch;
  const std::string path = scratch.file("steps.csv");
  auto error = [&](const std::vector<std::string>& columns, std::size_t rows) {
    try {
      CsvTable(path, columns).restore(rows);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error({"step"}, 0).find("is missing or unreadable"), std::string::npos);
  CsvTable({path, {"step", "lambda"}}).add_row({1LL, 0.5});
  EXPECT_NE(error({"step", "time"}, 1).find("does not have the columns this scene writes"), std::string::npos);
  EXPECT_NE(error({"step", "lambda"}, 2).find("has 1 rows, the checkpoint counted 2"), std::string::npos);
  EXPECT_EQ(error({"step", "lambda"}, 1), "no error");
}

}  // namespace
}  // namespace sinew::io
