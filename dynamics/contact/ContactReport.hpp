#pragma once
// What one contact evaluation found. The penalty force is the gradient of the potential
// k d^2 / 2 (PolygonPenetration), so `potential` is the energy the contact springs store now, and
// the damping part only ever removes energy, at the rate `dissipation_power`. The two split the
// work of the contact forces into stored and dissipated parts to first order in dt; the exact
// account for an energy balance is that work itself (ContactWork). Friction's slip work is
// booked apart (`friction_dissipated`, ContactFriction); its stick springs' energy is in
// `potential`.
#include <algorithm>

namespace vorodg {

struct ContactReport {
  int candidates = 0;                // cell pairs (or cells, for a plane) tested
  int contacts = 0;                  // penetrating vertices that got a force
  double potential = 0.0;            // sum of k d^2 / 2
  double dissipation_power = 0.0;    // sum of k_v <-v_n>^2 >= 0
  double friction_dissipated = 0.0;  // this evaluation's slip work, sum of mu |F_n| |slip|
  int sliding = 0;                   // contacts that slipped at this evaluation
  double max_depth = 0.0;
  int tunnelled = 0;    // penetrations left alone: first found deeper than a step can go
  int new_tunnels = 0;  // of those, the ones first found at this evaluation
  int late = 0;         // contacts found first deeper than a step goes: acting beyond that depth
  int new_late = 0;     // of those, the ones first found at this evaluation

  ContactReport& operator+=(const ContactReport& o) {
    candidates += o.candidates;
    contacts += o.contacts;
    tunnelled += o.tunnelled;
    new_tunnels += o.new_tunnels;
    late += o.late;
    new_late += o.new_late;
    potential += o.potential;
    dissipation_power += o.dissipation_power;
    friction_dissipated += o.friction_dissipated;
    sliding += o.sliding;
    max_depth = std::max(max_depth, o.max_depth);
    return *this;
  }
};

}  // namespace vorodg
