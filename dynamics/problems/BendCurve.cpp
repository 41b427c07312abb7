#include "dynamics/problems/BendCurve.hpp"

#include <cmath>
#include <set>

#include "core/io/AtomicFile.hpp"
#include "core/io/StateArchive.hpp"
#include "core/util/Format.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

constexpr const char* kHeader =
    "time,load_point_displacement,load,cmod,kinetic,elastic,external_work,reaction_work,"
    "cohesive_dissipated\n";

/// The distinct nodes of the pairs in the run's current map.
std::set<int> nodes_of(const std::vector<std::pair<int, int>>& pairs, const SplitDofMap& dofs) {
  std::set<int> nodes;
  for (const auto& [c, k] : pairs) nodes.insert(dofs.node(c, k));
  return nodes;
}

/// The mean of one displacement component over the nodes.
double mean_displacement(const std::set<int>& nodes, const Eigen::VectorXd& u, int component) {
  double sum = 0.0;
  for (int node : nodes) sum += u[2 * node + component];
  return sum / static_cast<double>(nodes.size());
}

}  // namespace

BendCurve::BendCurve(const PolygonMesh& mesh, const CentralDifference& run,
                     const BendGauges& gauges, DynamicsMeasures& m)
    : run_(run), gauges_(gauges) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    Point centre = Point::Zero();
    for (int v : loop) centre += mesh.vertex(v);
    centre /= static_cast<double>(loop.size());
    // A cell at the mouth lies on one side of the line: the notch (or the crack line) is its edge.
    for (int k = 0; k < static_cast<int>(loop.size()); ++k) {
      if (loop[k] == gauges.load_vertex) load_pairs_.push_back({c, k});
      if (loop[k] == gauges.mouth_vertex)
        mouth_pairs_[centre.x() > gauges.line_x ? 1 : 0].push_back({c, k});
    }
  }
  m.peak_load = 0.0;
  rows_ << kHeader;
}

double BendCurve::load() const {
  double r = 0.0;
  for (int node : nodes_of(load_pairs_, run_.dofs())) r += run_.reaction()[2 * node + 1];
  return -r * gauges_.thickness;
}

double BendCurve::displacement() const {
  return -mean_displacement(nodes_of(load_pairs_, run_.dofs()), run_.displacement(), 1);
}

double BendCurve::cmod() const {
  const SplitDofMap& dofs = run_.dofs();
  // Intact, both sides share the node and the difference is zero.
  return mean_displacement(nodes_of(mouth_pairs_[1], dofs), run_.displacement(), 0) -
         mean_displacement(nodes_of(mouth_pairs_[0], dofs), run_.displacement(), 0);
}

double BendCurve::kinetic_over_work() const {
  const StepRecord& r = run_.record();
  const double work = r.external_work + r.reaction_work;
  return work > 0.0 ? r.kinetic / work : NAN;
}

void BendCurve::observe(DynamicsMeasures& m) {
  const double load = this->load();
  if (load > m.peak_load) {
    m.peak_load = load;
    m.peak_load_displacement = displacement();
    m.peak_load_cmod = cmod();
    m.kinetic_over_work_at_peak = kinetic_over_work();
  }
  m.kinetic_over_work_end = kinetic_over_work();
  if (run_.step_count() % gauges_.every == 0) {
    rows_ << row();
    last_row_ = run_.step_count();
  }
}

std::string BendCurve::row() const {
  const StepRecord& r = run_.record();
  const double t = gauges_.thickness;
  std::ostringstream out;
  out << fmt(r.time, 12);
  for (double x :
       {displacement(), load(), cmod(), t * r.kinetic, t * r.elastic, t * r.external_work,
        t * r.reaction_work, cohesive_ ? t * cohesive_->dissipated_energy() : 0.0})
    out << ',' << fmt(x, 12);
  out << '\n';
  return out.str();
}

void BendCurve::write(const fs::path& out, const std::string& run) const {
  fs::create_directories(out / "curves");
  write_file_atomically(out / "curves" / (run + ".csv"),
                        rows_.str() + (last_row_ == run_.step_count() ? "" : row()));
}

void BendCurve::archive(StateArchive& a) {
  a.text("bend_curve.rows", rows_);
  a.value("bend_curve.last_row", last_row_);
}

}  // namespace vorodg
