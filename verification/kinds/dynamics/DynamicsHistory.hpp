#pragma once
// The history of one dynamics run: a CSV row every `history_every` steps, with the columns
//   step,time,kinetic_energy,elastic_energy,external_work,contact_work,dissipated_energy,
//   momentum_x,momentum_y
// and after them angular_momentum, reaction_work, kinetic_leapfrog, contact_potential,
// contacts, max_penetration, balance, balance_error, cohesive_work, bulk_viscosity_dissipation
// (docs/dynamics.md). The
// file is rewritten atomically at every flush, so a stopped run keeps a whole file with what it
// finished.
#include <filesystem>
#include <string>

#include "dynamics/ContactForces.hpp"
#include "dynamics/StepRecord.hpp"

namespace vorodg {

class StateArchive;

class DynamicsHistory {
 public:
  /// Nothing is written before the first flush.
  explicit DynamicsHistory(std::filesystem::path file);

  /// The header line (without the newline).
  static const char* columns();
  /// Appends the row of a step; `contact` may be null (no contact in the run).
  void add(const StepRecord& r, const ContactForces* contact);
  /// Rewrites the file with every row so far (atomically).
  void flush() const;
  const std::filesystem::path& file() const { return file_; }

  /// Saves or loads the rows so far (a checkpoint).
  void archive(StateArchive& a);

 private:
  std::filesystem::path file_;
  std::string text_;
};

}  // namespace vorodg
