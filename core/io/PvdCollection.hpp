#pragma once
// A ParaView collection (.pvd): the .vtu files of a series (time steps, load steps, sweep
// points), each with its value, opened in ParaView as one data set with a time axis. The file is
// rewritten atomically after every added entry, so a run that stops keeps what it finished.
#include <filesystem>
#include <string>
#include <vector>

namespace vorodg {

class StateArchive;

class PvdCollection {
 public:
  struct Entry {
    double value;      // the "timestep" attribute: a time, a step or a parameter value
    std::string file;  // relative to the .pvd's folder, '/'-separated
  };

  /// Nothing is written until the first entry is added.
  explicit PvdCollection(std::filesystem::path path) : path_(std::move(path)) {}

  /// Adds a data set and rewrites the collection. `file` is stored relative to the .pvd's
  /// folder (an absolute path is made relative to it). Throws InputError for a non-finite value
  /// or when the .pvd cannot be written.
  void add(double value, const std::filesystem::path& file);

  const std::vector<Entry>& entries() const { return entries_; }
  const std::filesystem::path& path() const { return path_; }
  /// The XML of the collection as it stands. Deterministic.
  std::string text() const;

  /// Saves or loads the entries (a checkpoint; the file is rewritten at the next add).
  void archive(StateArchive& a);

 private:
  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace vorodg
