#pragma once
// A study kind is a plug-in of the harness: its name, one line of doc, how a scene of that kind
// is read (which validates every key), and how its study runs and reports. The registry
// (verification/kinds/StudyKinds.cpp) lists every kind once; `vorodg run`, `vorodg run --list`,
// the scene fuzzer, messages naming the kinds and docs/scenes.md all take the kinds from it.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/schema/SceneKeys.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {

/// What `vorodg run` passes to a study kind.
struct StudyCall {
  std::filesystem::path scene;  // the scene file, absolute
  std::filesystem::path out;    // the output folder (a rerun resumes there)
  int threads = 2;
  bool progress = true;
  bool no_plots = false;
  bool force = false;  // dynamics: allow a step at or above the critical one
};

struct StudyKind {
  std::string name;
  std::string doc;
  /// Reads and validates a scene of this kind from its text (`source` names it in messages);
  /// returns its description. Throws InputError naming the file and the key.
  std::function<std::string(const std::string& text, const std::string& source)> read;
  /// Runs the scene's study into call.out and writes its reports; returns the exit code
  /// (0 done, 1 unexpected outcomes, 3 runs that broke down).
  std::function<int(const StudyCall& call)> run;
  /// Every key a scene of this kind may hold (`vorodg run --keys KIND`, docs/scenes.md).
  std::function<std::vector<SceneKey>()> keys;
};

/// Every kind, in the order messages and docs list them (verification/kinds/StudyKinds.cpp),
/// then those registered.
const std::vector<StudyKind>& study_kinds();

/// The kinds' names and docs, as a choice table (messages, `--keys`).
Choices study_choices();

/// Adds a kind (before any study runs: the list may move); a name already known is refused with
/// InputError. Returns true, so that a file can register at static initialization.
bool register_study_kind(StudyKind kind);

/// The kind of that name; throws InputError "<where>'<name>': expected <every kind>".
const StudyKind& study_kind(const std::string& name, const std::string& where);

/// The value of the scene's `study` key (default "convergence"), read without validating the
/// rest. Throws InputError if the text is not a JSON object or `study` is not a text.
std::string scene_study(const std::string& text, const std::string& source);
/// The kind the scene's `study` key names; throws InputError naming the key and every kind.
const StudyKind& scene_kind(const std::string& text, const std::string& source);

/// The kind's keys as a Markdown table: key, type, default, range, meaning (docs/scenes.md).
std::string key_table_markdown(const StudyKind& kind);

/// Reads any scene through its kind's reader: what `vorodg run` would accept or refuse.
std::string read_study_scene(const std::string& text, const std::string& source);

}  // namespace vorodg
