#pragma once
// A convergence table in the manner of deal.II's ConvergenceTable: fill it with values row by
// row, ask for rates between consecutive rows, then write it with any of the writers (console
// text, Markdown, CSV). The table holds numbers, never their text: formatting is the writers'.
#include <optional>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace vorodg {

/// How a column's numbers are printed by the text and Markdown writers (CSV is always exact).
struct ColumnStyle {
  int precision = 4;
  bool scientific = false;
  int spread_precision = 1;  // of the "± spread" part
};

class ConvergenceTable {
 public:
  using Style = ColumnStyle;

  /// Starts a new row; values added after it belong to it.
  void start_row();
  /// A number (with an optional spread, printed as "value ± spread") in `column` of the current
  /// row. A new column is appended to the right with `style`; a column keeps its first style.
  void add_value(const std::string& column, double value, std::optional<double> spread = {},
                 Style style = {});
  void add_text(const std::string& column, const std::string& text);
  /// Adds the column `<data> rate`: log(e_{i-1}/e_i) / log(h_{i-1}/h_i) between each row and
  /// the row above it where both have numbers in `data` and `reference` ("-" elsewhere).
  void evaluate_convergence_rates(const std::string& data, const std::string& reference);

  std::size_t rows() const { return rows_; }
  /// The number in (row, column), if there is one.
  std::optional<double> value(std::size_t row, const std::string& column) const;

  void write_text(std::ostream& out, const std::string& indent = "  ") const;
  void write_markdown(std::ostream& out) const;
  /// One header line, then one line per row; spreads get a column "<name> spread" of their own.
  void write_csv(std::ostream& out) const;

 private:
  struct Number {
    double value;
    std::optional<double> spread;
  };
  using Cell = std::variant<std::monostate, Number, std::string>;
  struct Column {
    std::string name;
    Style style;
    std::vector<Cell> cells;
  };
  Column& column(const std::string& name, Style style);
  const Column* find(const std::string& name) const;
  Cell& current(const std::string& name, Style style);
  static std::string format(const Cell& cell, const Style& style);
  static std::size_t display_width(const std::string& text);
  std::vector<std::vector<std::string>> formatted() const;

  std::vector<Column> columns_;
  std::size_t rows_ = 0;
};

}  // namespace vorodg
