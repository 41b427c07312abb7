#include "verification/kinds/dynamics/DynamicsHistory.hpp"

#include <cmath>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/io/StateArchive.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

DynamicsHistory::DynamicsHistory(std::filesystem::path file) : file_(std::move(file)) {
  text_ = std::string(columns()) + "\n";
}

const char* DynamicsHistory::columns() {
  return "step,time,kinetic_energy,elastic_energy,external_work,contact_work,dissipated_energy,"
         "momentum_x,momentum_y,angular_momentum,reaction_work,kinetic_leapfrog,contact_potential,"
         "contacts,max_penetration,balance,balance_error,cohesive_work,bulk_viscosity_dissipation";
}

void DynamicsHistory::add(const StepRecord& r, const ContactForces* contact) {
  const ContactReport c = contact ? contact->report() : ContactReport{};
  // The prescribed velocities' reactions are work done on the body from outside, like loads.
  const double external = r.external_work + r.reaction_work;
  const double drift = r.balance() - r.initial_balance;
  std::ostringstream row;
  row << r.step;
  for (double x : {r.time, r.kinetic, r.elastic, external, r.contact_work, r.damping_dissipation,
                   r.momentum.x(), r.momentum.y(), r.angular_momentum, r.reaction_work,
                   r.kinetic_leapfrog, c.potential})
    row << ',' << fmt(x, 12);
  row << ',' << c.contacts << ',' << fmt(c.max_depth, 12) << ',' << fmt(drift, 6) << ','
      << fmt(r.input_energy() > 0.0 ? std::abs(drift) / r.input_energy() : 0.0, 6) << ','
      << fmt(r.cohesive_work, 12) << ',' << fmt(r.bulk_viscosity_dissipation, 12) << '\n';
  text_ += row.str();
}

void DynamicsHistory::flush() const {
  write_file_atomically(file_, text_);
}

void DynamicsHistory::archive(StateArchive& a) {
  a.text("history.rows", text_);
}

}  // namespace vorodg
