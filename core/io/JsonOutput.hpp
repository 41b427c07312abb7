#pragma once
// JSON outputs: written atomically, with non-finite numbers refused rather than written as null.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/mesh/MeshStatistics.hpp"

namespace vorodg {

/// Writes `value` (pretty-printed) to `path` atomically. Throws NumericalError if it holds a
/// NaN or infinity, InputError if the path cannot be written.
void write_json(const std::filesystem::path& path, const nlohmann::json& value);

nlohmann::json to_json(const MeshStatistics& stats);
nlohmann::json histogram_json(const std::map<int, int>& histogram);

}  // namespace vorodg
