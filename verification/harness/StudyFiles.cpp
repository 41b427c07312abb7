#include "verification/harness/StudyFiles.hpp"

#include <cmath>

namespace vorodg {
namespace {

/// The value with every number that is not finite replaced by its text (RecordFields).
nlohmann::json finite_or_text(const nlohmann::json& value) {
  if (value.is_number_float() && !std::isfinite(value.get<double>()))
    return number_json(value.get<double>());
  nlohmann::json out = value;
  if (value.is_structured())
    for (auto it = out.begin(); it != out.end(); ++it) *it = finite_or_text(*it);
  return out;
}

}  // namespace

nlohmann::json summary_head(const std::string& scene, const std::string& study) {
  return {{"scene", scene}, {"study", study}};
}

void write_summary(const std::filesystem::path& out, const nlohmann::json& summary) {
  write_file_atomically(out / "summary.json", finite_or_text(summary).dump(1) + "\n");
}

}  // namespace vorodg
