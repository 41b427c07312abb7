#pragma once
// What the dynamic three-point bend measures (docs/dynamics.md, "Three-point bend"): after every
// step the load on the beam, from the reaction of the prescribed velocity at the load point, and
// its peak with the load point's displacement, the crack mouth opening and the kinetic energy
// over the work put in at that step; every time.output_every steps a row of the load-displacement
// and load-CMOD curve with the energies, written to curves/<run>.csv once the run ends (the
// quasi-static fracture study's file name, so the two overlay).
//
// The load point and the crack mouth are mesh vertices; the nodes at them change when cracks split
// them, so each reading looks them up through the run's current DOF map by (cell, vertex) pairs.
#include <Eigen/Core>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {

/// Where the beam is read: its load point and crack mouth (mesh vertices), the crack line's x,
/// the thickness every force and energy is multiplied by, and the rows' spacing in steps.
struct BendGauges {
  int load_vertex = -1, mouth_vertex = -1;
  double line_x = 0.0;
  double thickness = 1.0;
  int every = 1;
};

class BendCurve : public ProblemProbe {
 public:
  /// `mesh` and `run` (initialized) must outlive the probe; sets the peak's measures to 0 in `m`.
  BendCurve(const PolygonMesh& mesh, const CentralDifference& run, const BendGauges& gauges,
            DynamicsMeasures& m);

  void observe(DynamicsMeasures& m) override;
  void watch_cracks(const CohesiveForces& cohesive) override { cohesive_ = &cohesive; }
  /// curves/<run>.csv, atomically, with the last step's row if it fell between two samples.
  void write(const std::filesystem::path& out, const std::string& run) const override;

  /// The load, N: minus the y reaction summed over the load point's nodes, times the thickness
  /// (positive pushing down).
  double load() const;
  /// The load point's downward displacement, m (the mean of its nodes').
  double displacement() const;
  /// The crack mouth opening, m: u_x of the mouth's right-hand node minus its left-hand one's.
  double cmod() const;

  void archive(StateArchive& a) override;

 private:
  /// The curve's row at the current step.
  std::string row() const;
  /// Kinetic energy over the work put in (external and reactions); NaN before any work.
  double kinetic_over_work() const;

  const CentralDifference& run_;
  BendGauges gauges_;
  std::vector<std::pair<int, int>> load_pairs_;      // (cell, local vertex) at the load point
  std::vector<std::pair<int, int>> mouth_pairs_[2];  // at the mouth, left and right of the line
  const CohesiveForces* cohesive_ = nullptr;
  std::ostringstream rows_;
  long last_row_ = -1;  // the step of the last row
};

}  // namespace vorodg
