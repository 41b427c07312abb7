#include "verification/harness/RecordFields.hpp"

#include <algorithm>

namespace vorodg {

nlohmann::json number_json(double x) {
  if (std::isfinite(x)) return x;
  if (std::isnan(x)) return "nan";
  return x > 0 ? "inf" : "-inf";
}

double read_number(const nlohmann::json& j) {
  if (j.is_null()) return NAN;
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "nan") return NAN;
    if (s == "inf") return INFINITY;
    if (s == "-inf") return -INFINITY;
  }
  return j.get<double>();  // throws a type_error for any other text
}

std::string csv_cell(const nlohmann::json& value, const CsvFormat& format) {
  if (value.is_boolean()) return value.get<bool>() ? "1" : "0";
  if (value.is_string()) {
    const std::string& s = value.get_ref<const std::string&>();
    if (format.quoted) {
      std::string text = s;
      std::replace(text.begin(), text.end(), '"', '\'');
      return "\"" + text + "\"";
    }
    const bool non_finite = s == "nan" || s == "inf" || s == "-inf";
    return non_finite && format.blank_if_nan ? "" : s;
  }
  if (value.is_number_float()) return fmt(value.get<double>(), format.digits);
  return value.dump();  // integers
}

}  // namespace vorodg
