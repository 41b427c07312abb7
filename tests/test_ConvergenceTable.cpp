// The convergence table (verification/report/ConvergenceTable): values in, rates between rows,
// and three writers of the same data.
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

}  // namespace
}  // namespace vorodg
