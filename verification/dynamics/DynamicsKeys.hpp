#pragma once
// Every key of a dynamics scene in one table: its name, type, default, range and one-line doc.
// The reader (DynamicsScene.cpp) takes the fixed defaults and the numeric ranges from here, so
// they are written once; defaults that depend on the problem are stated here in words and
// computed by the reader. docs/dynamics.md lists the same table (a test checks every key is
// there).
#include <optional>
#include <string>
#include <vector>

namespace vorodg {

struct DynamicsKey {
  std::string name;      // full path in the scene: "time.safety"
  std::string type;      // as the docs write it
  std::string fallback;  // the default: a number, a word, or a rule in words
  std::string range;     // what is accepted, in words
  std::string doc;
  // Numeric bounds the reader enforces (none: any finite value, or checked by the reader).
  std::optional<double> lower, upper;
  bool lower_open = false, upper_open = false;
};

/// Every key, in the order the docs and the echo list them.
const std::vector<DynamicsKey>& dynamics_scene_keys();
/// The key of that full name; throws std::out_of_range for an unknown one (a programming error).
const DynamicsKey& dynamics_key(const std::string& name);
/// The default as a number; throws std::logic_error if it is not one.
double key_default(const DynamicsKey& key);
/// "expected <range>, found <value>" if the value is outside the key's bounds or not finite.
std::optional<std::string> check_key(const DynamicsKey& key, double value);

}  // namespace vorodg
