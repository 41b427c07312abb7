#include "dynamics/problems/FragmentMeasures.hpp"

#include <algorithm>
#include <vector>

#include "dynamics/problems/CrackLocations.hpp"

namespace vorodg {
namespace {

/// The mass in fragments of a single cell over the total: the sand.
double single_cell_mass_fraction(const Fragments& pieces) {
  double sand = 0.0;
  for (int f = 0; f < pieces.num_fragments(); ++f)
    if (pieces.num_cells(f) == 1) sand += pieces.mass(f);
  return sand / pieces.total_mass();
}

/// Where the broken edges are, from the first body's impact corner.
void measure_crack_locations(const Fragmentation& cracks, const ExplicitParameters& physics,
                             DynamicsMeasures& m) {
  const CohesiveForces& faces = cracks.cohesive();
  std::vector<int> broken;
  for (int e : faces.edges())
    if (faces.broken(e)) broken.push_back(e);
  const CrackLocations where =
      crack_locations(cracks.mesh(), broken, physics.bodies[0].domain, physics.wall->point);
  m.broken_near_impact = where.near_impact;
  m.broken_mid_length = where.mid_length;
  m.broken_elsewhere = where.elsewhere;
}

}  // namespace

Fragments measure_fragments(const Fragmentation& cracks, const ExplicitParameters& physics,
                            const LumpedMass& mass, DynamicsMeasures& m) {
  const CohesiveForces& faces = cracks.cohesive();
  const DynamicFracture& fracture = cracks.fracture();
  Fragments pieces(fracture.broken_state(), mass.pair_masses());
  m.fragments = pieces.num_fragments();
  m.max_fragment_mass_fraction = pieces.largest_mass_fraction();
  m.single_cell_mass_fraction = single_cell_mass_fraction(pieces);
  m.main_body_rotation = cracks.main_body_rotation(pieces, mass);
  m.dissipated_energy = faces.dissipated_energy();
  m.cracked_edges = static_cast<double>(faces.edges().size());
  m.broken_edges = faces.num_broken();
  m.face_friction_dissipated = faces.friction_dissipated_energy();
  if (physics.wall) measure_crack_locations(cracks, physics, m);
  m.released_edges = static_cast<double>(faces.released_edges().size());
  if (const InterfaceActivation* activation = cracks.activation()) {
    m.activated_interfaces = activation->activated();
    m.activation_work = activation->activation_work() / std::max(cracks.input_energy(), 1e-300);
  }
  m.check_seconds = fracture.times().check;
  m.rebuild_seconds = fracture.times().rebuild;
  m.law_balance_error = cracks.worst_balance();
  m.law_balance_breach_time = cracks.breach_time();
  return pieces;
}

}  // namespace vorodg
