#pragma once
// Quasi-static cohesive fracture at cell interfaces in the DG form (docs/fracture.md). The space
// splits only where the scene lets cracks form (SplitDofMap over the crack-capable edges); the
// bulk is the shared cell kernel; every split edge carries two interface points whose state picks
// the term (CohesiveInterfaces). This object evaluates forces, tangents and energies for a given
// displacement and interface state; QuasiStaticPath drives it along the load path.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <optional>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/solve/BlockPattern.hpp"
#include "core/solve/ProportionalConstraints.hpp"
#include "core/util/Stopwatch.hpp"
#include "dg/CohesiveInterfaces.hpp"
#include "dg/DgElasticity.hpp"
#include "fracture/CohesiveLaw.hpp"
#include "fracture/FractureSetup.hpp"
#include "fracture/MohrCoulomb.hpp"

namespace vorodg {

/// Energies of a state, times the thickness.
struct FractureEnergies {
  double elastic = 0.0;       // the bulk: a(u, u) / 2
  double coupling = 0.0;      // what the intact interfaces' SIPG terms store
  double cohesive = 0.0;      // recoverable energy of cohesive faces and overclosure
  double dissipated = 0.0;    // the cohesive law's dissipation
  double crack_length = 0.0;  // faces past the strength (not the notch)
  // What the bookkeeping loses when intact points turn cohesive: their coupling energy less
  // the law's energy at their opening (nonzero where the weakly continuous field had a jump).
  double switched = 0.0;
  double stored() const { return elastic + coupling + cohesive; }
  /// Everything the external work went into.
  double accounted() const { return stored() + dissipated + switched; }
};

/// A crack face past the strength (softening or open) in some state of the interface points.
struct CrackedFace {
  Point a, b;         // its ends
  bool open = false;  // both its points open
};

class CohesiveFracture {
 public:
  /// `coupling` chooses the intact faces' penalty, weights and traction as for dg-sipg.
  /// `initial_stiffness` is K0 of the intrinsic law on pre-inserted faces (unused otherwise).
  CohesiveFracture(const ElementTable& table, const ElasticityIntegrator& integrator,
                   const FractureSetup& setup, const CohesiveParameters& law,
                   const MohrCoulombParameters& criterion, const DgOptions& coupling,
                   int threads = 1);

  /// A strength varying from edge to edge (MaterialVariation::edge_strength: one factor per
  /// mesh edge) for the crack faces' law and criterion; the bulk stays uniform. Call before
  /// setup_system.
  void set_edge_strength(std::vector<double> factor);
  void setup_system();

  int num_dofs() const { return space_->num_dofs(); }
  int num_free_dofs() const { return constraints_->num_free(); }
  const DgSpace& space() const { return *space_; }
  const ProportionalConstraints& constraints() const { return *constraints_; }
  const std::vector<InterfacePoint>& initial_points() const { return initial_points_; }
  const CohesiveInterfaces& interfaces() const { return *interfaces_; }
  const FractureSetup& setup() const { return setup_; }
  /// The DOFs the crack faces' terms act on: both ends of every split edge on both sides (a
  /// shape function's trace on an edge is its two ends' only). With the faces' points in fixed
  /// states (pre-inserted), every other entry of the tangent is the bulk's and never changes.
  std::vector<int> face_end_dofs() const;

  /// Internal forces of u (per unit thickness) and, if asked, the tangent on all DOFs (always
  /// in the same pattern, so that the solver can restrict it in place).
  /// `points` comes in as the committed state and leaves as the trial state at u.
  Eigen::VectorXd forces(const Eigen::VectorXd& u, std::vector<InterfacePoint>& points,
                         Eigen::SparseMatrix<double>* tangent) const;
  /// The force the machine applies, in newtons: thickness x the work-conjugate of the stroke.
  double load(const Eigen::VectorXd& force) const;
  /// The stroke at the load point (the prescribed displacement's magnitude).
  double stroke(double lambda) const;
  /// The crack mouth opening displacement: a linear functional, gauge . u.
  const Eigen::VectorXd& mouth_gauge() const { return gauge_; }
  FractureEnergies energies(const Eigen::VectorXd& u,
                            const std::vector<InterfacePoint>& points) const;
  /// Intact points that the cracking mode lets crack now.
  std::vector<int> eligible_points(const std::vector<InterfacePoint>& points) const;
  /// The faces past the strength at `points`: a point of them has dissipated (the notch's faces
  /// left out).
  std::vector<CrackedFace> cracked_faces(const std::vector<InterfacePoint>& points) const;
  /// Each cell's worst interface state at `points`: 0 intact, 1 cohesive, 2 open.
  std::vector<double> cell_interface_states(const std::vector<InterfacePoint>& points) const;
  const StageTimes& seconds() const { return seconds_; }

 private:
  std::vector<char> crack_capable() const;
  void assemble_base(const ElasticityIntegrator::CellMatrices& cells);
  void build_constraints();
  void build_gauge();

  const ElementTable& table_;
  const ElasticityIntegrator& integrator_;
  FractureSetup setup_;
  CohesiveLaw law_;
  MohrCoulomb criterion_;
  DgOptions coupling_;
  int threads_;
  std::optional<SplitDofMap> map_;
  std::unique_ptr<DgSpace> space_;
  std::unique_ptr<InterfaceOperators> ops_;
  std::unique_ptr<InterfacePenalty> penalty_;
  std::unique_ptr<CohesiveInterfaces> interfaces_;
  std::optional<ProportionalConstraints> constraints_;
  std::optional<BlockPattern> pattern_;
  Eigen::SparseMatrix<double> bulk_;  // all DOFs, in the pattern
  Eigen::SparseMatrix<double> base_;  // bulk + every interface coupled as if intact
  std::vector<InterfacePoint> initial_points_;
  std::vector<double> edge_strength_;  // per mesh edge; empty: uniform
  Eigen::VectorXd gauge_;
  StageTimes seconds_;
};

}  // namespace vorodg
