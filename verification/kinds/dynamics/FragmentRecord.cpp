#include "verification/kinds/dynamics/FragmentRecord.hpp"

#include <algorithm>
#include <string_view>
#include <utility>
#include <vector>

#include "core/io/AtomicFile.hpp"
#include "fracture/Fragments.hpp"
#include "verification/kinds/dynamics/CrackLocations.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

/// The mass in fragments of a single cell over the total: the sand.
double single_cell_mass_fraction(const Fragments& pieces) {
  double sand = 0.0;
  for (int f = 0; f < pieces.num_fragments(); ++f)
    if (pieces.num_cells(f) == 1) sand += pieces.mass(f);
  return sand / pieces.total_mass();
}

}  // namespace

void record_fragments(const Fragmentation& cracks, const DynamicsScene& scene,
                      const LumpedMass& mass, const fs::path& out, const std::string& id,
                      DynamicsMeasures& m) {
  const CohesiveForces& faces = cracks.cohesive();
  const DynamicFracture& fracture = cracks.fracture();
  const Fragments pieces(fracture.broken_state(), mass.pair_masses());
  m.fragments = pieces.num_fragments();
  m.max_fragment_mass_fraction = pieces.largest_mass_fraction();
  m.single_cell_mass_fraction = single_cell_mass_fraction(pieces);
  m.main_body_rotation = cracks.main_body_rotation(pieces, mass);
  m.dissipated_energy = faces.dissipated_energy();
  m.cracked_edges = static_cast<double>(faces.edges().size());
  m.broken_edges = faces.num_broken();
  m.face_friction_dissipated = faces.friction_dissipated_energy();
  if (scene.wall) {  // where the broken edges are, from the first body's impact corner
    std::vector<int> broken;
    for (int e : faces.edges())
      if (faces.broken(e)) broken.push_back(e);
    const CrackLocations where =
        crack_locations(cracks.mesh(), broken, scene.bodies[0].domain, scene.wall->point);
    m.broken_near_impact = where.near_impact;
    m.broken_mid_length = where.mid_length;
    m.broken_elsewhere = where.elsewhere;
  }
  m.released_edges = static_cast<double>(faces.released_edges().size());
  if (const InterfaceActivation* activation = cracks.activation()) {
    m.activated_interfaces = activation->activated();
    m.activation_work = activation->activation_work() / std::max(cracks.input_energy(), 1e-300);
  }
  m.check_seconds = fracture.times().check;
  m.rebuild_seconds = fracture.times().rebuild;
  m.law_balance_error = cracks.worst_balance();
  m.law_balance_breach_time = cracks.breach_time();
  const Eigen::Matrix2Xd v = pieces.velocities(cracks.run().dofs(), cracks.run().velocity());
  ConvergenceTable f;  // fragments/<run>.csv: what each fragment is and where it goes
  for (const char* column : {"fragment", "mass", "cells", "x", "y", "vx", "vy"})
    f.declare_column(column,
                     std::string_view(column) == "fragment" || std::string_view(column) == "cells"
                         ? integer_style()
                         : shortest_csv_style());
  for (int i = 0; i < pieces.num_fragments(); ++i) {
    f.start_row();
    for (const auto& [column, value] : {std::pair{"fragment", double(i)},
                                        {"mass", pieces.mass(i)},
                                        {"cells", double(pieces.num_cells(i))},
                                        {"x", pieces.centres()(0, i)},
                                        {"y", pieces.centres()(1, i)},
                                        {"vx", v(0, i)},
                                        {"vy", v(1, i)}})
      f.add_value(column, value);
  }
  fs::create_directories(out / "fragments");
  write_file_atomically(out / "fragments" / (id + ".csv"), csv_text(f));
  ConvergenceTable c;  // cracks/<run>.csv: the step at which each edge cracked
  for (const char* column : {"step", "edge"}) c.declare_column(column, integer_style());
  for (const CrackEvent& e : fracture.events()) {
    c.start_row();
    c.add_value("step", static_cast<double>(e.step));
    c.add_value("edge", e.edge);
  }
  fs::create_directories(out / "cracks");
  write_file_atomically(out / "cracks" / (id + ".csv"), csv_text(c));
}

}  // namespace vorodg
