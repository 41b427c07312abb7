#pragma once
// Reads a scene's keys against its kind's KeyTable: each read takes the key's default and bounds
// from the table, refuses a value outside them with one line naming the file and the key
// (expected against found), and notes the value used, so that the echo at the top of a run and
// summary.json list every key with its value in the table's order. The kinds' readers derive
// from it and add what is particular to them (keys whose default depends on the problem, keys
// that exclude each other).
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/schema/SceneKeys.hpp"
#include "core/schema/SceneObject.hpp"

namespace vorodg {

/// "[1, 2.5]": numbers as the shortest text that reads back, without -0.
std::string vector_text(std::initializer_list<double> v);
std::string point_text(const Point& p);
std::string rect_text(const Rectangle& r);

/// The number at `name` in `o` (absent: `fallback`), refused with one line naming it where it is
/// outside the bounds of `key`: for readers that read an object's keys without a table reader.
double checked_number(SceneObject& o, const std::string& name, const SceneKey& key,
                      double fallback);

/// Prints "#   key = value" for every key used: the echo at the top of a study part.
void echo_settings(const std::vector<std::pair<std::string, std::string>>& settings);
class SceneKeyReader {
 public:
  /// Refuses a key of the table's old spellings at once, naming its new one.
  SceneKeyReader(const KeyTable& table, const nlohmann::json& root, const std::string& source);

  /// Every key that was read and the value used, in the table's order.
  std::vector<std::pair<std::string, std::string>> settings() const;

  // Each read below takes the default and the bounds of `full` from the table and notes the
  // value used. Public: the parts of a kind (its problems) read their own keys through them.

  /// The object at a top-level key (an empty one if absent).
  SceneObject object(const std::string& key);
  static std::string leaf(const std::string& full) { return full.substr(full.rfind('.') + 1); }
  void note(const std::string& key, const std::string& value) { notes_[key] = value; }

  double number(SceneObject& o, const std::string& full, std::optional<double> fallback = {});
  int integer(SceneObject& o, const std::string& full, std::optional<int> fallback = {});
  bool flag(SceneObject& o, const std::string& full, std::optional<bool> fallback = {});
  /// `allowed`: the accepted words, each with a space either side; `fallback` replaces the
  /// table's default where that depends on the scene.
  std::string word(SceneObject& o, const std::string& full, const std::string& allowed,
                   const std::optional<std::string>& fallback = {});
  Point point(SceneObject& o, const std::string& full, const Point& fallback);
  Rectangle rectangle(SceneObject& o, const std::string& full, const Rectangle& fallback);
  /// The top-level object of the scene.
  SceneObject& top() { return top_; }

 protected:
  const KeyTable& table_;
  const std::string& source_;
  SceneObject top_;
  std::map<std::string, std::string> notes_;
};

}  // namespace vorodg
