#include "core/io/JsonOutput.hpp"

#include <cmath>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

void check_finite(const nlohmann::json& value, const std::string& where) {
  if (value.is_number_float() && !std::isfinite(value.get<double>()))
    throw NumericalError("output value '" + where + "' is not finite; refusing to write it");
  if (value.is_object())
    for (const auto& [key, item] : value.items()) check_finite(item, where + "." + key);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i)
      check_finite(value[i], where + "[" + std::to_string(i) + "]");
}

}  // namespace

void write_json(const std::filesystem::path& path, const nlohmann::json& value) {
  check_finite(value, path.filename().string());
  write_file_atomically(path, value.dump(2) + "\n");
}

nlohmann::json histogram_json(const std::map<int, int>& histogram) {
  nlohmann::json out = nlohmann::json::object();
  for (auto [key, count] : histogram) out[std::to_string(key)] = count;
  return out;
}

nlohmann::json to_json(const MeshStatistics& s) {
  return {{"cells", s.cells},
          {"vertices", s.vertices},
          {"edges", s.edges},
          {"boundary_edges", s.boundary_edges},
          {"h_avg", s.h_avg},
          {"min_edge", s.min_edge},
          {"max_edge", s.max_edge},
          {"min_edge_over_h_avg", s.min_edge_over_h},
          {"min_interior_angle_deg", s.min_interior_angle_deg},
          {"max_interior_angle_deg", s.max_interior_angle_deg},
          {"area_error", s.area_error},
          {"most_common_sides", s.most_common_sides},
          {"side_counts_after", histogram_json(s.side_counts)}};
}

}  // namespace vorodg
