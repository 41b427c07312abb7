#pragma once
// Reads one JSON object of a scene, knowing its place ("meshes[1]") for messages, and refusing
// keys it was not asked about (with the nearest known key suggested).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace vorodg {

/// Levenshtein distance, for "did you mean" suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b);

class SceneObject {
 public:
  SceneObject(const nlohmann::json& value, std::string where, const std::string& source);

  [[noreturn]] void fail(const std::string& key, const std::string& expected,
                         const nlohmann::json& found) const;
  [[noreturn]] void fail_value(const std::string& key, const std::string& what) const;

  bool has(const std::string& key);
  const nlohmann::json& at(const std::string& key);
  std::string text(const std::string& key, const std::string& fallback);
  double number(const std::string& key, double fallback);
  int integer(const std::string& key, int fallback);
  bool flag(const std::string& key, bool fallback);
  /// A number or a list of numbers (at least one).
  std::vector<double> numbers(const std::string& key, std::vector<double> fallback);
  std::vector<std::string> texts(const std::string& key, std::vector<std::string> fallback);
  /// After reading: any key not asked about is an error, with the nearest known key suggested.
  void finish() const;
  /// The key's full path in the scene ("formulations[1].kp").
  std::string path(const std::string& key) const;
  const std::string& source() const { return source_; }

 private:
  void known(const std::string& key) { asked_.insert(key); }
  static std::string describe(const nlohmann::json& v);

  const nlohmann::json& value_;
  std::string where_;
  const std::string& source_;
  std::set<std::string> asked_;
};

}  // namespace vorodg
