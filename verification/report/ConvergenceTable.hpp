#pragma once
// A convergence table in the manner of deal.II's ConvergenceTable: fill it with values row by
// row, ask for rates between consecutive rows, then write it with any of the writers (console
// text, Markdown, CSV). The table holds numbers, never their text: formatting is the writers'.
// It is the one table writer of the reports: a column's style says how each writer shows it
// (digits, its CSV name, whether it is in the CSV or only in the text and Markdown tables), so
// that a report's Markdown table and its CSV file are filled once.
#include <optional>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace vorodg {

/// How a column is printed by the text and Markdown writers, and by the CSV writer.
struct ColumnStyle {
  int precision = 4;
  bool scientific = false;
  int spread_precision = 1;  // of the "± spread" part
  // CSV
  int csv_precision = 17;  // significant digits (17: exact; 0: the shortest text that reads back)
  std::string csv_name = "";  // its header in the CSV, if not the column's name
  bool csv_quoted = true;     // texts in double quotes (theirs doubled)
  bool in_csv = true;         // false: only in the text and Markdown tables
  bool in_text = true;        // false: only in the CSV
  std::string missing = "-";  // an empty cell in the text and Markdown tables
};

/// Counts and indices: every digit in every writer.
ColumnStyle integer_style();
/// Data a program reads back: the shortest exact text in the CSV, nowhere else.
ColumnStyle shortest_csv_style();

struct CsvOptions {
  bool quote_names = true;  // the header's names in double quotes
};

class ConvergenceTable;
/// The table as CSV text with plain header names (the data files of runs and reports).
std::string csv_text(const ConvergenceTable& table);

class ConvergenceTable {
 public:
  using Style = ColumnStyle;

  /// A column, placed now to the right of the others (else it is placed when first filled).
  void declare_column(const std::string& name, Style style = {});
  /// Starts a new row; values added after it belong to it.
  void start_row();
  /// A number (with an optional spread, printed as "value ± spread") in `column` of the current
  /// row. A new column is appended to the right with `style`; a column keeps its first style.
  void add_value(const std::string& column, double value, std::optional<double> spread = {},
                 Style style = {});
  void add_text(const std::string& column, const std::string& text, Style style = {});
  /// Adds the column `<data> rate`: log(e_{i-1}/e_i) / log(h_{i-1}/h_i) between each row and
  /// the row above it where both have numbers in `data` and `reference` ("-" elsewhere).
  void evaluate_convergence_rates(const std::string& data, const std::string& reference);

  std::size_t rows() const { return rows_; }
  /// The number in (row, column), if there is one.
  std::optional<double> value(std::size_t row, const std::string& column) const;

  void write_text(std::ostream& out, const std::string& indent = "  ") const;
  void write_markdown(std::ostream& out) const;
  /// One header line, then one line per row; spreads get a column "<name> spread" of their own.
  void write_csv(std::ostream& out, const CsvOptions& options = {}) const;

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
