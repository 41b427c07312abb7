#include "dg/CohesiveFracture.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {

CohesiveFracture::CohesiveFracture(const ElementTable& table,
                                   const ElasticityIntegrator& integrator,
                                   const FractureSetup& setup, const CohesiveParameters& law,
                                   const MohrCoulombParameters& criterion,
                                   const DgOptions& coupling, int threads)
    : table_(table),
      integrator_(integrator),
      setup_(setup),
      law_(law),
      criterion_(criterion),
      coupling_(coupling),
      threads_(std::max(threads, 1)) {
  const int edges = table.mesh().num_edges();
  if (static_cast<int>(setup.line.size()) != edges || static_cast<int>(setup.notch.size()) != edges)
    throw InputError("fracture setup: line and notch flags must have one entry per mesh edge");
  if ((setup.mode == CrackingMode::pre_inserted) != law_.intrinsic())
    throw InputError(setup.mode == CrackingMode::pre_inserted
                         ? "cracking mode pre-inserted: the law needs an initial stiffness > 0"
                         : "an initial stiffness belongs to pre-inserted faces only");
  if (!(setup.thickness > 0.0)) throw InputError("thickness: expected > 0");
}

/// Edges across which the DOFs split: the notch and wherever the mode lets a crack form.
std::vector<char> CohesiveFracture::crack_capable() const {
  const PolygonMesh& mesh = table_.mesh();
  std::vector<char> capable(mesh.num_edges(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    capable[e] = !mesh.edge(e).on_boundary() && (setup_.notch[e] || setup_.line[e] ||
                                                 cracks_anywhere(setup_.mode) || setup_.split_all);
  return capable;
}

void CohesiveFracture::set_edge_strength(std::vector<double> factor) {
  if (interfaces_)
    throw InputError("cohesive fracture: the strength may vary only before setup_system");
  edge_strength_ = std::move(factor);
}

void CohesiveFracture::setup_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  std::vector<char> connected = crack_capable();
  for (char& c : connected) c = !c;
  map_.emplace(mesh, connected);
  space_ = std::make_unique<DgSpace>(mesh, *map_);
  ops_ = std::make_unique<InterfaceOperators>(*space_, integrator_, table_);
  seconds_["dof_map"] = clock.seconds();

  clock.restart();
  const auto cells = integrator_.all_cell_matrices(threads_);
  seconds_["cell_matrices"] = clock.seconds();
  clock.restart();
  coupling_.formulation = "dg-sipg";
  penalty_ = std::make_unique<InterfacePenalty>(
      *ops_, integrator_, cells, penalty_scaling(coupling_), penalty_multiplier(coupling_),
      coupling_.weighted_average, interface_traction(coupling_), threads_);
  interfaces_ = std::make_unique<CohesiveInterfaces>(
      *ops_, *penalty_, interface_traction(coupling_), law_, criterion_);
  interfaces_->set_edge_strength(edge_strength_);
  initial_points_.assign(interfaces_->num_points(), InterfacePoint{});
  for (int p = 0; p < interfaces_->num_points(); ++p) {
    const int e = interfaces_->face(p).edge;
    if (setup_.notch[e])
      initial_points_[p].state = PointState::open;
    else if (setup_.line[e] && setup_.mode == CrackingMode::pre_inserted)
      initial_points_[p].state = PointState::cohesive;
  }
  seconds_["interfaces"] = clock.seconds();
  clock.restart();
  assemble_base(cells);
  seconds_["assembly"] = clock.seconds();
  build_constraints();
  build_gauge();
}

void CohesiveFracture::build_constraints() {
  const PolygonMesh& mesh = table_.mesh();
  std::vector<PrescribedDof> prescribed;
  for (const VertexConstraint& c : setup_.constraints) {
    if (c.vertex < 0 || c.vertex >= mesh.num_vertices() || c.component < 0 || c.component > 1)
      throw InputError("fracture setup: constraint on vertex " + std::to_string(c.vertex) +
                       ", component " + std::to_string(c.component) + " is out of range");
    for (int node : map_->vertex_nodes(c.vertex))
      prescribed.push_back({2 * node + c.component, c.reference});
  }
  constraints_.emplace(prescribed, num_dofs());
}

void CohesiveFracture::build_gauge() {
  gauge_ = Eigen::VectorXd::Zero(num_dofs());
  const PolygonMesh& mesh = table_.mesh();
  const MouthGauge& g = setup_.mouth;
  for (std::size_t i = 0; i < g.vertices.size(); ++i) {
    const int v = g.vertices[i];
    int left = -1, right = -1;
    double x_left = INFINITY, x_right = -INFINITY;
    for (int c : mesh.vertex_cells(v)) {
      const auto loop = mesh.cell_vertices(c);
      const int k = static_cast<int>(std::find(loop.begin(), loop.end(), v) - loop.begin());
      const double x = mesh.cell_centroid(c).x();
      if (x < x_left) x_left = x, left = space_->dof(c, k);
      if (x > x_right) x_right = x, right = space_->dof(c, k);
    }
    if (left == right) continue;  // not split here
    gauge_[right] += g.weights[i];
    gauge_[left] -= g.weights[i];
  }
}

/// The tangent's pattern (cell blocks, then interface blocks), the bulk stiffness and the base:
/// the bulk plus every interface coupled as if all its points were intact.
void CohesiveFracture::assemble_base(const ElasticityIntegrator::CellMatrices& cells) {
  const PolygonMesh& mesh = table_.mesh();
  std::vector<std::vector<int>> blocks;
  for (int c = 0; c < mesh.num_cells(); ++c) blocks.push_back(space_->cell_dofs(c));
  for (int i = 0; i < interfaces_->num_faces(); ++i) blocks.push_back(interfaces_->dofs(i));
  pattern_.emplace(num_dofs(), blocks);
  bulk_ = pattern_->zero_matrix();
  for (int c = 0; c < mesh.num_cells(); ++c)
    pattern_->add(c, cells.block(c, space_->cell_dof_count(c)), bulk_);
  base_ = bulk_;
  interfaces_->add_intact(
      [&](int i, const Eigen::MatrixXd& K) { pattern_->add(mesh.num_cells() + i, K, base_); });
}

Eigen::VectorXd CohesiveFracture::forces(const Eigen::VectorXd& u,
                                         std::vector<InterfacePoint>& points,
                                         Eigen::SparseMatrix<double>* tangent) const {
  Eigen::VectorXd f = base_ * u;
  if (!tangent) {
    interfaces_->add(u, points, f, nullptr);
    return f;
  }
  *tangent = base_;  // same pattern: the non-intact faces' corrections go in place
  const int first_face = table_.mesh().num_cells();
  const CohesiveInterfaces::BlockSink sink = [&](int i, const Eigen::MatrixXd& K) {
    pattern_->add(first_face + i, K, *tangent);
  };
  interfaces_->add(u, points, f, &sink);
  return f;
}

double CohesiveFracture::load(const Eigen::VectorXd& force) const {
  return setup_.thickness * constraints_->conjugate(force);
}

double CohesiveFracture::stroke(double lambda) const {
  for (const VertexConstraint& c : setup_.constraints)
    if (c.reference != 0.0) return lambda * std::abs(c.reference);
  return lambda;
}

FractureEnergies CohesiveFracture::energies(const Eigen::VectorXd& u,
                                            const std::vector<InterfacePoint>& points) const {
  const InterfaceEnergies e = interfaces_->energies(u, points);
  const double t = setup_.thickness;
  FractureEnergies out;
  out.elastic = t * 0.5 * u.dot(bulk_ * u);
  out.coupling = t * e.coupling;
  out.cohesive = t * e.cohesive;
  out.dissipated = t * e.dissipated;
  out.crack_length = e.crack_length;
  return out;
}

std::vector<int> CohesiveFracture::face_end_dofs() const {
  std::vector<int> dofs;
  for (const Interface& f : space_->interfaces())
    for (int s = 0; s < 2; ++s)
      for (int first : {f.dof_v0[s], f.dof_v1[s]}) dofs.push_back(first), dofs.push_back(first + 1);
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

std::vector<int> CohesiveFracture::eligible_points(
    const std::vector<InterfacePoint>& points) const {
  std::vector<int> out;
  if (setup_.mode == CrackingMode::pre_inserted) return out;
  const PolygonMesh& mesh = table_.mesh();
  // Contiguous: a face may crack only if it touches a vertex of the notch or of a cracked face.
  std::vector<char> crack_vertex(mesh.num_vertices(), 0);
  if (setup_.mode == CrackingMode::contiguous)
    for (int p = 0; p < interfaces_->num_points(); ++p)
      if (points[p].state != PointState::intact) {
        const MeshEdge& edge = mesh.edge(interfaces_->face(p).edge);
        crack_vertex[edge.v0] = crack_vertex[edge.v1] = 1;
      }
  for (int p = 0; p < interfaces_->num_points(); ++p) {
    if (points[p].state != PointState::intact) continue;
    const MeshEdge& edge = mesh.edge(interfaces_->face(p).edge);
    const bool allowed =
        setup_.mode == CrackingMode::arbitrary ||
        (setup_.mode == CrackingMode::restricted && setup_.line[interfaces_->face(p).edge]) ||
        (setup_.mode == CrackingMode::contiguous &&
         (crack_vertex[edge.v0] || crack_vertex[edge.v1]));
    if (allowed) out.push_back(p);
  }
  return out;
}

std::vector<CrackedFace> CohesiveFracture::cracked_faces(
    const std::vector<InterfacePoint>& points) const {
  std::vector<CrackedFace> faces;
  for (int p = 0; p + 1 < static_cast<int>(points.size()); p += 2) {
    const Interface& f = interfaces_->face(p);
    if (setup_.notch[f.edge]) continue;
    bool cracked = false, open = true;
    for (int q = p; q < p + 2; ++q) {
      cracked |= interfaces_->law(q).dissipated_energy(points[q].history.max_opening) > 0.0;
      open &= points[q].state == PointState::open;
    }
    if (cracked) faces.push_back({f.a, f.b, open});
  }
  return faces;
}

std::vector<double> CohesiveFracture::cell_interface_states(
    const std::vector<InterfacePoint>& points) const {
  std::vector<double> state(table_.mesh().num_cells(), 0.0);
  for (int p = 0; p < static_cast<int>(points.size()); ++p) {
    const double s = points[p].state == PointState::open       ? 2.0
                     : points[p].state == PointState::cohesive ? 1.0
                                                               : 0.0;
    for (int c : interfaces_->face(p).cell) state[c] = std::max(state[c], s);
  }
  return state;
}

}  // namespace vorodg
