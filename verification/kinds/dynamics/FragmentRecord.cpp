#include "verification/kinds/dynamics/FragmentRecord.hpp"

#include <string_view>
#include <utility>

#include "core/io/AtomicFile.hpp"
#include "dynamics/problems/FragmentMeasures.hpp"
#include "fracture/Fragments.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace fs = std::filesystem;

namespace vorodg {

void record_fragments(const Fragmentation& cracks, const DynamicsScene& scene,
                      const LumpedMass& mass, const fs::path& out, const std::string& id,
                      DynamicsMeasures& m) {
  const Fragments pieces = measure_fragments(cracks, scene, mass, m);
  const DynamicFracture& fracture = cracks.fracture();
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
