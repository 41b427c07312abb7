#include "verification/report/ConvergenceTable.hpp"

#include <algorithm>
#include <charconv>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "verification/report/RateFit.hpp"

namespace vorodg {

ColumnStyle integer_style() {
  ColumnStyle s;
  s.precision = 17;
  return s;
}

ColumnStyle shortest_csv_style() {
  ColumnStyle s;
  s.csv_precision = 0, s.csv_quoted = false, s.in_text = false;
  return s;
}

namespace {

/// A number in the CSV: with `precision` significant digits, or its shortest exact text.
void put_csv_number(std::ostream& out, double x, int precision) {
  if (precision > 0) {
    out << std::defaultfloat << std::setprecision(precision) << x;
    return;
  }
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  out << std::string_view(buffer, end - buffer);
}

}  // namespace

void ConvergenceTable::start_row() {
  ++rows_;
  for (Column& c : columns_) c.cells.resize(rows_);
}

ConvergenceTable::Column& ConvergenceTable::column(const std::string& name, Style style) {
  for (Column& c : columns_)
    if (c.name == name) return c;
  columns_.push_back({name, style, std::vector<Cell>(rows_)});
  return columns_.back();
}

const ConvergenceTable::Column* ConvergenceTable::find(const std::string& name) const {
  for (const Column& c : columns_)
    if (c.name == name) return &c;
  return nullptr;
}

ConvergenceTable::Cell& ConvergenceTable::current(const std::string& name, Style style) {
  if (rows_ == 0) throw std::logic_error("ConvergenceTable: add a value after start_row()");
  return column(name, style).cells[rows_ - 1];
}

void ConvergenceTable::add_value(const std::string& name, double value,
                                 std::optional<double> spread, Style style) {
  current(name, style) = Number{value, spread};
}

void ConvergenceTable::add_text(const std::string& name, const std::string& text, Style style) {
  current(name, style) = text;
}

void ConvergenceTable::declare_column(const std::string& name, Style style) {
  column(name, style);
}

std::optional<double> ConvergenceTable::value(std::size_t row, const std::string& name) const {
  const Column* c = find(name);
  if (!c || row >= c->cells.size()) return std::nullopt;
  if (const Number* n = std::get_if<Number>(&c->cells[row])) return n->value;
  return std::nullopt;
}

void ConvergenceTable::evaluate_convergence_rates(const std::string& data,
                                                  const std::string& reference) {
  std::vector<Cell> rates(rows_);
  for (std::size_t i = 1; i < rows_; ++i) {
    const auto e0 = value(i - 1, data), e1 = value(i, data);
    const auto h0 = value(i - 1, reference), h1 = value(i, reference);
    if (e0 && e1 && h0 && h1) rates[i] = Number{pair_rate(*h0, *e0, *h1, *e1), std::nullopt};
  }
  // The rate column stands right after its data column, as deal.II places it.
  const auto after = std::find_if(columns_.begin(), columns_.end(),
                                  [&](const Column& c) { return c.name == data; });
  if (after == columns_.end()) throw std::logic_error("ConvergenceTable: no column '" + data + "'");
  columns_.insert(after + 1, Column{data + " rate", Style{3, false}, rates});
}

std::string ConvergenceTable::format(const Cell& cell, const Style& style) {
  if (const std::string* text = std::get_if<std::string>(&cell)) return *text;
  const Number* n = std::get_if<Number>(&cell);
  if (!n) return style.missing;
  std::ostringstream os;
  auto put = [&](double x, int precision) {
    if (style.scientific)
      os << std::scientific << std::setprecision(precision) << x;
    else
      os << std::defaultfloat << std::setprecision(precision) << x;
  };
  put(n->value, style.precision);
  if (n->spread) os << " ± ", put(*n->spread, style.spread_precision);
  return os.str();
}

std::vector<std::vector<std::string>> ConvergenceTable::formatted() const {
  std::vector<std::vector<std::string>> table(rows_ + 1);
  for (const Column& c : columns_) {
    if (!c.style.in_text) continue;
    table[0].push_back(c.name);
    for (std::size_t r = 0; r < rows_; ++r) table[r + 1].push_back(format(c.cells[r], c.style));
  }
  return table;
}

std::size_t ConvergenceTable::display_width(const std::string& text) {
  // Characters, not bytes: "±" is two bytes of UTF-8 but one column on a terminal.
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char ch) { return (ch & 0xC0) != 0x80; }));
}

void ConvergenceTable::write_text(std::ostream& out, const std::string& indent) const {
  const auto table = formatted();
  std::vector<std::size_t> width(table[0].size(), 0);
  for (const auto& row : table)
    for (std::size_t c = 0; c < row.size(); ++c)
      width[c] = std::max(width[c], display_width(row[c]));
  for (const auto& row : table) {
    out << indent;
    for (std::size_t c = 0; c < row.size(); ++c)
      out << (c ? "  " : "") << std::string(width[c] - display_width(row[c]), ' ') << row[c];
    out << "\n";
  }
}

void ConvergenceTable::write_markdown(std::ostream& out) const {
  const auto table = formatted();
  for (std::size_t r = 0; r < table.size(); ++r) {
    out << "|";
    for (const std::string& cell : table[r]) {
      out << " ";
      for (char ch : cell) out << (ch == '|' ? "\\|" : std::string(1, ch));  // not a cell border
      out << " |";
    }
    out << "\n";
    if (r == 0) {
      out << "|";
      for (std::size_t c = 0; c < table[0].size(); ++c) out << "---|";
      out << "\n";
    }
  }
}

void ConvergenceTable::write_csv(std::ostream& out, const CsvOptions& options) const {
  auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return q + "\"";
  };
  auto name = [&](const std::string& s) { return options.quote_names ? quoted(s) : s; };
  std::vector<const Column*> listed;
  std::vector<bool> has_spread;
  for (const Column& c : columns_) {
    if (!c.style.in_csv) continue;
    listed.push_back(&c);
    has_spread.push_back(std::any_of(c.cells.begin(), c.cells.end(), [](const Cell& x) {
      const Number* n = std::get_if<Number>(&x);
      return n && n->spread;
    }));
  }
  for (std::size_t c = 0; c < listed.size(); ++c) {
    const std::string& header =
        listed[c]->style.csv_name.empty() ? listed[c]->name : listed[c]->style.csv_name;
    out << (c ? "," : "") << name(header);
    if (has_spread[c]) out << "," << name(header + " spread");
  }
  out << "\n";
  for (std::size_t r = 0; r < rows_; ++r) {
    for (std::size_t c = 0; c < listed.size(); ++c) {
      const Cell& cell = listed[c]->cells[r];
      const ColumnStyle& style = listed[c]->style;
      out << (c ? "," : "");
      const Number* n = std::get_if<Number>(&cell);
      if (n)
        put_csv_number(out, n->value, style.csv_precision);
      else if (const std::string* t = std::get_if<std::string>(&cell))
        out << (style.csv_quoted ? quoted(*t) : *t);
      if (has_spread[c]) {
        out << ",";
        if (n && n->spread) put_csv_number(out, *n->spread, style.csv_precision);
      }
    }
    out << "\n";
  }
}

std::string csv_text(const ConvergenceTable& table) {
  std::ostringstream csv;
  table.write_csv(csv, {.quote_names = false});
  return csv.str();
}

}  // namespace vorodg
