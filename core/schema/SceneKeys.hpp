#pragma once
// The one schema type of scene keys: every key of a study kind with its name, type, default,
// range and one-line doc. A kind's table (KeyTable) is the only place its keys' defaults and
// numeric bounds are written: its reader (SceneKeyReader) takes them from there, the echo and
// summary.json list the values used in the table's order, and docs/scenes.md lists the same
// rows (a test checks every key of every kind). Every number a scene can hold has a finite
// lower and upper bound: generous limits of what the physics allows, so that a value that
// would overflow the run is refused as bad input instead.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/util/Bounds.hpp"

namespace vorodg {

struct SceneKey {
  std::string name;      // full path in the scene: "time.safety"
  std::string type;      // as the docs write it: number, integer, string, bool, [x, y], ...
  std::string fallback;  // the default: a number, a word, or a rule in words
  std::string range;     // what is accepted, in words (messages and docs)
  std::string doc;
  // The bounds the reader enforces on a number (none: not a number, or checked by the reader).
  Bounds bounds;
  bool is_number() const { return type == "number" || type == "integer"; }
};

/// A key without numeric bounds (texts, flags, lists, points).
SceneKey key(std::string name, std::string type, std::string fallback, std::string range,
             std::string doc);
/// A number with bounds: lower (open or closed) and upper (open or closed).
SceneKey bounded(std::string name, std::string type, std::string fallback, std::string range,
                 std::string doc, double lower, bool lower_open, double upper,
                 bool upper_open = false);

/// Appends `more` to `keys` (a kind's table spliced from shared groups).
inline void append_keys(std::vector<SceneKey>& keys, const std::vector<SceneKey>& more) {
  keys.insert(keys.end(), more.begin(), more.end());
}

/// What a rectangle key (`domain`) accepts: the reader checks it (SceneKeyReader::rectangle).
inline constexpr const char* kRectangleRange = "x0 < x1, y0 < y1, each |coordinate| <= 1e6";
inline constexpr double kCoordinateLimit = 1e6;  // m: a body larger than 1000 km is a typo

/// The keys of one study kind, in the order the docs and the echo list them.
struct KeyTable {
  std::string kind;  // "fracture", "dynamics": for messages
  std::vector<SceneKey> keys;
  /// Old spellings refused with a message naming the new one (no silent aliases).
  std::vector<std::pair<std::string, std::string>> renamed;
  /// The key of that full name; throws std::out_of_range for an unknown one (a programming
  /// error: the readers only ask for keys of their table).
  const SceneKey& at(const std::string& name) const;
};

/// The default as a number; throws std::logic_error if it is not one.
double key_default(const SceneKey& key);
/// "expected <range>, found <value>" if the value is outside the key's bounds or not finite.
std::optional<std::string> check_key(const SceneKey& key, double value);

}  // namespace vorodg
