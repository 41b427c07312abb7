#include "verification/kinds/dynamics/DynamicsMeasureFields.hpp"

namespace vorodg {

const std::vector<std::pair<const char*, double DynamicsMeasures::*>>& dynamics_measure_fields() {
  using M = DynamicsMeasures;
  static const std::vector<std::pair<const char*, double M::*>> fields = {
      {"energy_balance_error", &M::energy_balance_error},
      {"max_energy_balance_error", &M::max_energy_balance_error},
      {"momentum_drift", &M::momentum_drift},
      {"angular_momentum_drift", &M::angular_momentum_drift},
      {"arrival_time", &M::arrival_time},
      {"arrival_theory", &M::arrival_theory},
      {"wave_speed", &M::wave_speed},
      {"wave_speed_theory", &M::wave_speed_theory},
      {"wave_speed_error", &M::wave_speed_error},
      {"max_penetration", &M::max_penetration},
      {"max_penetration_over_h", &M::max_penetration_over_h},
      {"tunnelled_contacts", &M::tunnelled_contacts},
      {"late_contacts", &M::late_contacts},
      {"impact_velocity", &M::impact_velocity},
      {"rebound_velocity", &M::rebound_velocity},
      {"rebound_estimate", &M::rebound_estimate},
      {"contact_time", &M::contact_time},
      {"contact_time_estimate", &M::contact_time_estimate},
      {"peak_wall_force", &M::peak_wall_force},
      {"peak_wall_force_estimate", &M::peak_wall_force_estimate},
      {"peak_wall_force_window", &M::peak_wall_force_window},
      {"wall_impulse", &M::wall_impulse},
      {"penalty_ratio", &M::penalty_ratio},
      {"rear_strike_time", &M::rear_strike_time},
      {"peak_load", &M::peak_load},
      {"peak_load_displacement", &M::peak_load_displacement},
      {"peak_load_cmod", &M::peak_load_cmod},
      {"kinetic_over_work_at_peak", &M::kinetic_over_work_at_peak},
      {"kinetic_over_work_end", &M::kinetic_over_work_end},
      {"contact_friction_dissipated", &M::contact_friction_dissipated},
      {"face_friction_dissipated", &M::face_friction_dissipated},
      {"contact_velocity_dissipated", &M::contact_velocity_dissipated},
      {"bulk_viscosity_dissipated", &M::bulk_viscosity_dissipated},
      {"fragments", &M::fragments},
      {"max_fragment_mass_fraction", &M::max_fragment_mass_fraction},
      {"single_cell_mass_fraction", &M::single_cell_mass_fraction},
      {"main_body_rotation", &M::main_body_rotation},
      {"dissipated_energy", &M::dissipated_energy},
      {"cracked_edges", &M::cracked_edges},
      {"broken_edges", &M::broken_edges},
      {"broken_near_impact", &M::broken_near_impact},
      {"broken_mid_length", &M::broken_mid_length},
      {"broken_elsewhere", &M::broken_elsewhere},
      {"released_edges", &M::released_edges},
      {"activated_interfaces", &M::activated_interfaces},
      {"activation_work", &M::activation_work},
      {"check_seconds", &M::check_seconds},
      {"rebuild_seconds", &M::rebuild_seconds},
      {"coupling_seconds", &M::coupling_seconds},
      {"law_balance_error", &M::law_balance_error},
      {"law_balance_breach_time", &M::law_balance_breach_time},
      {"max_rotation", &M::max_rotation},
      {"large_rotation_time", &M::large_rotation_time}};
  return fields;
}

}  // namespace vorodg
