// Damaged data files give a clear error, never a crash or a value read from the
// damage (docs/robustness.md): the committed surrogate of the linear law and the
// committed certified table reference_data/cor_report_grid.csv, cut short at many
// places and corrupted in their structure, are each refused with a parse_error
// that names the file. (A changed digit inside a number keeps both files well
// formed: only a checksum of the file can catch that.)
#include "required_dependencies.hpp"

#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/tables/reference_table.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The surrogate read from `text`, or the parse_error's message ("" if it was accepted).
std::string surrogate_error(const std::string& text) {
  std::istringstream in(text);
  try {
    (void)viscor::surrogate::read_cor_surrogate(in, "damaged.surrogate");
  } catch (const viscor::parse_error& e) {
    return e.what();
  }
  return "";
}

std::string table_error(const std::string& text) {
  try {
    (void)viscor::parse_table(text, "damaged.csv");
  } catch (const viscor::parse_error& e) {
    return e.what();
  }
  return "";
}

// `text` with its `n`-th line (0-based) replaced by `line`.
std::string with_line(const std::string& text, std::size_t n, const std::string& line) {
  std::size_t start = 0;
  for (std::size_t k = 0; k < n; ++k) start = text.find('\n', start) + 1;
  const std::size_t end = text.find('\n', start);
  return text.substr(0, start) + line + text.substr(end);
}

std::string line_of(const std::string& text, std::size_t n) {
  std::size_t start = 0;
  for (std::size_t k = 0; k < n; ++k) start = text.find('\n', start) + 1;
  return text.substr(start, text.find('\n', start) - start);
}

// Line number of the first line starting with `prefix`.
std::size_t line_starting(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  std::string line;
  for (std::size_t n = 0; std::getline(in, line); ++n)
    if (line.rfind(prefix, 0) == 0) return n;
  return std::string::npos;
}

class CorruptSurrogate : public ::testing::Test {
 protected:
  void SetUp() override {
    text = file_text(std::string(VISCOR_SOURCE_DIR) + "/reference_data/surrogates/linear.surrogate");
    if (text.empty()) VISCOR_SKIP_OR_FAIL_MISSING("reference_data/surrogates/linear.surrogate");
    ASSERT_EQ(surrogate_error(text), "") << "the committed file itself must read";
  }
  std::string text;
};

TEST_F(CorruptSurrogate, TruncatedAnywhereIsRefused) {
  // 40 cuts spread over the file, inside numbers and between them, and the last
  // bytes before the closing "end": each loses at least the closing word.
  std::vector<std::size_t> cuts = {0, 1, 20, 21, text.size() - 5, text.size() - 3, text.size() - 2};
  for (std::size_t k = 1; k < 34; ++k) cuts.push_back(text.size() * k / 34 + k);
  for (const std::size_t cut : cuts) {
    const std::string message = surrogate_error(text.substr(0, cut));
    EXPECT_NE(message, "") << "a surrogate cut after " << cut << " of " << text.size() << " bytes was accepted";
    EXPECT_NE(message.find("damaged.surrogate: surrogate file:"), std::string::npos) << message;
  }
}

TEST_F(CorruptSurrogate, BrokenStructureIsRefused) {
  const std::size_t low = line_starting(text, "low_load "), high = line_starting(text, "high_load ");
  ASSERT_NE(low, std::string::npos);
  ASSERT_NE(high, std::string::npos);
  std::istringstream header(line_of(text, low));
  std::string word, x0, x1, y0, y1, order, nodes, patches;
  header >> word >> x0 >> x1 >> y0 >> y1 >> order >> nodes >> patches;
  const std::string root = line_of(text, low + 1);  // "dim child split" of the root node
  ASSERT_EQ(root.rfind("0 1 ", 0) == 0 || root.rfind("1 1 ", 0) == 0, true) << root;
  const std::vector<std::pair<std::string, std::string>> damages = {
      {"unknown version", with_line(text, 0, "viscor-cor-surrogate 7")},
      {"node count one too many",
       with_line(text, low, "low_load " + x0 + " " + x1 + " " + y0 + " " + y1 + " " + order + " " +
                                std::to_string(std::stoll(nodes) + 1) + " " + patches)},
      {"a box of no width", with_line(text, low, "low_load " + x0 + " " + x0 + " " + y0 + " " + y1 + " " + order + " " +
                                                     nodes + " " + patches)},
      {"the root its own child (a cycle)", with_line(text, low + 1, root.substr(0, 2) + "0" + root.substr(3))},
      {"a node outside the tree", with_line(text, low + 1, root.substr(0, 2) + "3" + root.substr(3))},
      {"a word for a number", with_line(text, low + 1 + std::stoull(nodes), "x 1 2 3")},
      {"a non-finite domain", with_line(text, 2, "domain 1 -0.5 inf")},
      {"an empty domain", with_line(text, 2, "domain 1 10000 -0.5")},
      {"a negative bound", with_line(text, 4, "bound -1e-13 1e-14 1e-13 2")},
      {"text after the end", text + "end\n"},
  };
  for (const auto& [what, damaged] : damages) {
    ASSERT_NE(damaged, text) << what;
    const std::string message = surrogate_error(damaged);
    EXPECT_NE(message.find("damaged.surrogate: surrogate file:"), std::string::npos)
        << what << ": " << (message.empty() ? "accepted" : message);
  }
}

class CorruptTable : public ::testing::Test {
 protected:
  void SetUp() override {
    text = file_text(std::string(VISCOR_SOURCE_DIR) + "/reference_data/cor_report_grid.csv");
    if (text.empty()) VISCOR_SKIP_OR_FAIL_MISSING("reference_data/cor_report_grid.csv");
    ASSERT_EQ(table_error(text), "") << "the committed table itself must read";
  }
  std::string text;
};

TEST_F(CorruptTable, CutInsideALineIsRefused) {
  // The first 400 rows (each cut is read from the start: the whole table 40 times is slow under the sanitizers).
  std::size_t end = 0;
  for (int line = 0; line < 401; ++line) end = text.find('\n', end) + 1;
  text.resize(end);
  for (std::size_t k = 1; k < 40; ++k) {
    std::size_t cut = text.size() * k / 40 + 7 * k;
    if (text[cut - 1] == '\n') ++cut;  // a cut at a line end leaves a shorter, valid table
    const std::string message = table_error(text.substr(0, cut));
    EXPECT_NE(message.find("damaged.csv:"), std::string::npos) << "cut at " << cut << ": " << message;
    EXPECT_NE(message.find("truncated row"), std::string::npos) << message;
  }
  // As --resume reads a .partial file: the cut row is dropped, never read as a shorter number.
  const std::size_t cut = text.size() / 2 + 3;
  ASSERT_NE(text[cut - 1], '\n');
  const viscor::csv_table t = viscor::parse_table(text.substr(0, cut), "damaged.csv", true);
  EXPECT_TRUE(t.truncated_tail);
  for (const auto& row : t.rows) EXPECT_NE(text.find(row.text + "\n"), std::string::npos);
}

TEST_F(CorruptTable, DamagedRowsAreRefused) {
  std::size_t end = 0;
  for (int line = 0; line < 101; ++line) end = text.find('\n', end) + 1;
  text.resize(end);  // the first 100 rows
  const std::string row = line_of(text, 5);  // index,law,alpha,beta,gamma,g,outcome,e,one_minus_e,...
  auto field_replaced = [&](std::size_t column, const std::string& value) {
    std::vector<std::string> f = viscor::split_fields(row);
    f.at(column) = value;
    std::string line;
    for (std::size_t k = 0; k < f.size(); ++k) line += (k ? "," : "") + f[k];
    return with_line(text, 5, line);
  };
  const std::vector<std::tuple<std::string, std::string, std::string>> damages = {
      {"e above 1", field_replaced(7, "1.5"), "field e"},
      {"e not a number", field_replaced(7, "0.9x"), "field e"},
      {"a negative gamma", field_replaced(4, "-0.1"), "field gamma"},
      {"an unknown outcome", field_replaced(6, "bounce"), "field outcome"},
      {"a law with other exponents", field_replaced(2, "2"), "field law"},
      {"digits not an integer", field_replaced(11, "3.5"), "field digits"},
      {"a field lost", with_line(text, 5, row.substr(0, row.rfind(','))), "expected 13 fields"},
      {"CR-LF line end", with_line(text, 5, row + "\r"), "CR-LF"},
      {"a wrong header", with_line(text, 0, "index,law,alpha"), "wrong columns"},
  };
  for (const auto& [what, damaged, expected] : damages) {
    const std::string message = table_error(damaged);
    EXPECT_NE(message.find("damaged.csv:"), std::string::npos) << what << ": " << (message.empty() ? "accepted" : message);
    EXPECT_NE(message.find(expected), std::string::npos) << what << ": " << message;
  }
  // A row given twice is refused when the table is written out (table merge).
  const viscor::csv_table twice = viscor::parse_table(text + row + "\n", "damaged.csv");
  EXPECT_THROW((void)viscor::table_text(twice.kind, twice.rows, "damaged.csv"), viscor::parse_error);
}

}  // namespace
