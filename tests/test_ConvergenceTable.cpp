// The convergence table (verification/report/ConvergenceTable): values in, rates between rows,
// and three writers of the same data; a column's style says how each writer shows it (its CSV
// name and digits, the shortest exact text, plain or quoted texts, columns in one writer only,
// the text of an empty cell), and a declared column keeps its place when its first row is empty.
#include "verification/report/ConvergenceTable.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace vorodg {
namespace {

ConvergenceTable two_levels() {
  ConvergenceTable t;
  const ColumnStyle sci{3, true};
  t.start_row();
  t.add_value("h", 0.1);
  t.add_value("error", 1e-2, 1e-3, sci);
  t.start_row();
  t.add_value("h", 0.05);
  t.add_value("error", 2.5e-3, std::nullopt, sci);
  t.add_text("note", "fine");
  t.evaluate_convergence_rates("error", "h");
  return t;
}

TEST(ConvergenceTable, RatesBetweenConsecutiveRows) {
  const ConvergenceTable t = two_levels();
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_FALSE(t.value(0, "error rate").has_value());
  EXPECT_NEAR(*t.value(1, "error rate"), 2.0, 1e-14);
  EXPECT_FALSE(t.value(0, "note").has_value());  // text is not a number
}

TEST(ConvergenceTable, MarkdownHasAHeaderASeparatorAndTheRateAfterItsColumn) {
  std::ostringstream md;
  two_levels().write_markdown(md);
  EXPECT_EQ(md.str(),
            "| h | error | error rate | note |\n"
            "|---|---|---|---|\n"
            "| 0.1 | 1.000e-02 ± 1.0e-03 | - | - |\n"
            "| 0.05 | 2.500e-03 | 2 | fine |\n");
}

TEST(ConvergenceTable, TextIsAlignedOnTheScreen) {
  std::ostringstream text;
  two_levels().write_text(text, "");
  // Row 1 holds a "±" (two bytes, one character), row 2 none: aligned means equal characters.
  EXPECT_EQ(text.str(),
            "   h                error  error rate  note\n"
            " 0.1  1.000e-02 ± 1.0e-03           -     -\n"
            "0.05            2.500e-03           2  fine\n");
}

TEST(ConvergenceTable, CsvIsExactAndGivesSpreadsAColumn) {
  std::ostringstream csv;
  two_levels().write_csv(csv);
  EXPECT_EQ(csv.str(),
            "\"h\",\"error\",\"error spread\",\"error rate\",\"note\"\n"
            "0.10000000000000001,0.01,0.001,,\n"
            "0.050000000000000003,0.0025000000000000001,,2,\"fine\"\n");
}

TEST(ConvergenceTable, ValuesNeedARow) {
  ConvergenceTable t;
  EXPECT_THROW(t.add_value("h", 1.0), std::logic_error);
  EXPECT_THROW(t.evaluate_convergence_rates("missing", "h"), std::logic_error);
}

TEST(ConvergenceTable, StylesSayHowEachWriterShowsAColumn) {
  ColumnStyle h{4}, only_csv, only_text, plain, blank{2};
  h.csv_name = "h_avg", h.csv_precision = 3;
  only_csv.in_text = false;
  only_text.in_csv = false;
  plain.csv_quoted = false;
  blank.missing = "";
  ConvergenceTable t;
  t.declare_column("mesh", plain);
  t.declare_column("h [m]", h);
  t.declare_column("sd", only_csv);  // empty in the first row: still the third column
  t.declare_column("shown", only_text);
  t.declare_column("drift", blank);
  t.declare_column("cells", integer_style());
  t.declare_column("mass", shortest_csv_style());
  t.start_row();
  t.add_text("mesh", "rcp, fine");
  t.add_value("h [m]", 0.123456);
  t.add_text("shown", "1 \u00b1 0.1");
  t.add_value("cells", 12345678);
  t.add_value("mass", 0.1);
  t.start_row();
  t.add_text("mesh", "hex");
  t.add_value("h [m]", 0.0625);
  t.add_value("sd", 0.5);
  t.add_value("drift", 1.5e-3);
  t.add_value("cells", 7);
  t.add_value("mass", 1.0 / 3.0);
  std::ostringstream csv, md;
  t.write_csv(csv, {.quote_names = false});
  EXPECT_EQ(csv.str(),
            "mesh,h_avg,sd,drift,cells,mass\n"
            "rcp, fine,0.123,,,12345678,0.1\n"
            "hex,0.0625,0.5,0.0015,7,0.3333333333333333\n");
  t.write_markdown(md);
  EXPECT_EQ(md.str(),
            "| mesh | h [m] | shown | drift | cells |\n|---|---|---|---|---|\n"
            "| rcp, fine | 0.1235 | 1 \u00b1 0.1 |  | 12345678 |\n"
            "| hex | 0.0625 | - | 0.0015 | 7 |\n");
  EXPECT_EQ(csv_text(t), csv.str());
}

}  // namespace
}  // namespace vorodg
