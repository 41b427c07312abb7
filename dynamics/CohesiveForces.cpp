#include "dynamics/CohesiveForces.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"
#include "fracture/FacePoint.hpp"

namespace vorodg {
namespace {

/// The local index of edge e in cell c's loop.
int local_edge(const PolygonMesh& mesh, int c, int e) {
  const auto edges = mesh.cell_edges(c);
  for (int k = 0; k < static_cast<int>(edges.size()); ++k)
    if (edges[k] == e) return k;
  throw InputError("cohesive forces: edge " + std::to_string(e) + " is not an edge of cell " +
                   std::to_string(c));
}

}  // namespace

CohesiveForces::CohesiveForces(const PolygonMesh& mesh, const CohesiveLaw& law)
    : mesh_(mesh), law_(law), slot_(mesh.num_edges(), -1) {
  if (!law.intrinsic())
    throw InputError(
        "cohesive.initial_stiffness: expected > 0 in dynamics (an extrinsic law's unloading "
        "stiffness has no bound, and the explicit step would have none either)");
}

CohesiveForces::Face CohesiveForces::make_face(const PolygonMesh& mesh, int e) {
  if (e < 0 || e >= mesh.num_edges())
    throw InputError("cohesive forces: edge " + std::to_string(e) + ": expected 0 .. " +
                     std::to_string(mesh.num_edges() - 1));
  const MeshEdge& edge = mesh.edge(e);
  if (edge.cell1 < 0)
    throw InputError("cohesive forces: edge " + std::to_string(e) + " is on the boundary");
  Face f;
  f.edge = e;
  const int k0 = local_edge(mesh, edge.cell0, e), k1 = local_edge(mesh, edge.cell1, e);
  const int n0 = mesh.cell_size(edge.cell0), n1 = mesh.cell_size(edge.cell1);
  // cell0 runs v0 -> v1 along its edge k0; cell1 runs v1 -> v0 along its edge k1.
  f.side0 = {k0, (k0 + 1) % n0};
  f.side1 = {(k1 + 1) % n1, k1};
  const Point d = mesh.vertex(edge.v1) - mesh.vertex(edge.v0);
  f.length = d.norm();
  f.t = d / f.length;
  f.n = Eigen::Vector2d(f.t.y(), -f.t.x());  // outward from cell0 (counter-clockwise)
  return f;
}

void CohesiveForces::set_edge_strength(std::vector<double> factor) {
  if (!faces_.empty())
    throw InputError("cohesive forces: the strength may vary only before any edge cracks");
  if (!factor.empty() && static_cast<int>(factor.size()) != mesh_.num_edges())
    throw InputError("cohesive forces: " + std::to_string(factor.size()) +
                     " edge strengths, expected " + std::to_string(mesh_.num_edges()));
  edge_strength_ = std::move(factor);
}

void CohesiveForces::set_closure(ClosureStiffness closure) {
  require_parameter(
      std::isfinite(closure.fraction) && closure.fraction > 0.0 && closure.fraction <= 1.0,
      "cohesive forces: closure stiffness (of K0)", closure.fraction, "0 < fraction <= 1");
  if (!faces_.empty()) throw InputError("cohesive forces: the closure is set before any crack");
  if (!closure.per_edge.empty() && static_cast<int>(closure.per_edge.size()) != mesh_.num_edges())
    throw InputError("cohesive forces: " + std::to_string(closure.per_edge.size()) +
                     " closure stiffnesses, expected " + std::to_string(mesh_.num_edges()));
  for (std::size_t e = 0; e < closure.per_edge.size(); ++e)
    require_parameter(std::isfinite(closure.per_edge[e]) && closure.per_edge[e] > 0.0,
                      "cohesive forces: closure stiffness of edge " + std::to_string(e),
                      closure.per_edge[e], "> 0");
  closure_ = std::move(closure);
}

void CohesiveForces::set_friction(double mu) {
  require_parameter(std::isfinite(mu) && mu >= 0.0 && mu <= 10.0, "cohesive forces: friction", mu,
                    "0 <= mu <= 10");
  friction_ = mu;
}

CohesiveLaw CohesiveForces::edge_law(int e) const {
  return law_.with_strength_factor(edge_strength_[e]);
}

void CohesiveForces::add_edge(int e) {
  Face f = make_face(mesh_, e);
  if (slot_[e] >= 0)
    throw InputError("cohesive forces: edge " + std::to_string(e) + " is already cracked");
  if (!edge_strength_.empty()) {
    try {
      face_laws_.push_back(edge_law(e));
    } catch (const InputError& error) {
      throw InputError("cohesive forces: edge " + std::to_string(e) + " with strength x " +
                       std::to_string(edge_strength_[e]) + ": " + error.what());
    }
  }
  f.closure = closure_.of_edge(e, law_.parameters().initial_stiffness);
  slot_[e] = static_cast<int>(faces_.size());
  faces_.push_back(f);
  edges_.push_back(e);
}

Eigen::Vector2d CohesiveForces::carrying_opening(const CohesiveLaw& law, double k,
                                                 const Eigen::Vector2d& traction) {
  const CohesiveParameters& p = law.parameters();
  const double beta2 = p.shear_factor * p.shear_factor;
  // On the elastic branch tau = K0 (<d_n>, beta^2 d_t); a closed face's normal traction is the
  // closure penalty's, k d_n.
  Eigen::Vector2d s(traction[0] >= 0.0 ? traction[0] / p.initial_stiffness : traction[0] / k,
                    beta2 > 0.0 ? traction[1] / (beta2 * p.initial_stiffness) : 0.0);
  const double effective = std::hypot(std::max(s[0], 0.0), p.shear_factor * s[1]);
  const double peak = p.strength / p.initial_stiffness;
  if (effective > peak) {  // beyond the law's strength: the peak, in the carried direction
    if (s[0] > 0.0) s[0] *= peak / effective;
    s[1] *= peak / effective;
  }
  return s;
}

void CohesiveForces::add_edge(int e, const Carried& carried) {
  add_edge(e);
  Face& face = faces_.back();
  const CohesiveLaw& law = law_of(faces_.size() - 1);
  const SegmentRule& rule = gauss2_segment();
  for (int q = 0; q < 2; ++q) {
    QuadraturePoint& p = face.points[q];
    const Eigen::Vector2d s = carrying_opening(law, face.closure, carried.traction[q]);
    const Eigen::Vector2d& g = carried.jump[q];
    p.shift = s - Eigen::Vector2d(g.dot(face.n), g.dot(face.t));
    FacePointResponse r = face_point_response(law, s, face.closure, p.history);
    p.friction.slip = s[1];  // the stick spring starts unstressed
    const double w = rule.weights[q] * face.length;
    p.opening = s;
    p.traction = r.traction;
    p.jump = g;
    p.force = w * (r.traction[0] * face.n + r.traction[1] * face.t);
    continuation_energy_ += w * face_point_stored_energy(law, s, face.closure, p.history);
  }
}

void CohesiveForces::bind(const SplitDofMap& dofs) {
  for (Face& f : faces_) bind_face(dofs, f);
}

void CohesiveForces::rebind(const SplitDofMap& dofs, std::span<const int> vertices) {
  // A face at v is an edge of a cell at v (found from both its cells: bound twice, harmless).
  for (int v : vertices)
    for (int c : mesh_.vertex_cells(v))
      for (int e : mesh_.cell_edges(c))
        if (slot_[e] >= 0 && (mesh_.edge(e).v0 == v || mesh_.edge(e).v1 == v))
          bind_face(dofs, faces_[slot_[e]]);
}

void CohesiveForces::bind_face(const SplitDofMap& dofs, Face& f) const {
  const MeshEdge& edge = mesh_.edge(f.edge);
  for (int j = 0; j < 2; ++j) {
    f.node0[j] = dofs.node(edge.cell0, f.side0[j]);
    f.node1[j] = dofs.node(edge.cell1, f.side1[j]);
  }
}

CohesiveForces::Frame CohesiveForces::frame(const Face& face, const Eigen::VectorXd& u) const {
  if (!turning_) return {face.n, face.t, Eigen::Vector2d::Zero(), 0.0};
  const MeshEdge& edge = mesh_.edge(face.edge);
  auto mean_end = [&](int j) {
    return Eigen::Vector2d(0.5 *
                           (u.segment<2>(2 * face.node0[j]) + u.segment<2>(2 * face.node1[j])));
  };
  const Eigen::Vector2d d =
      mesh_.vertex(edge.v1) + mean_end(1) - mesh_.vertex(edge.v0) - mean_end(0);
  const double length = d.norm();
  if (!(length > 1e-9 * face.length))  // crushed flat: the reference frame
    return {face.n, face.t, d, 0.0};
  const Eigen::Vector2d t = d / length;
  return {Eigen::Vector2d(t.y(), -t.x()), t, d, length};  // as make_face builds them
}

void CohesiveForces::add_chord_force(const Face& face, const Eigen::Vector2d& force,
                                     Eigen::VectorXd& f) {
  for (const auto& nodes : {face.node0, face.node1}) {
    f.segment<2>(2 * nodes[1]) -= 0.5 * force;
    f.segment<2>(2 * nodes[0]) += 0.5 * force;
  }
}

void CohesiveForces::evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& f) {
  const SegmentRule& rule = gauss2_segment();
  double work = 0.0;
  for (std::size_t slot = 0; slot < faces_.size(); ++slot) {
    Face& face = faces_[slot];
    if (face.released) continue;
    const CohesiveLaw& law = law_of(slot);
    const Frame fr = frame(face, u);
    const Eigen::Vector2d& n = fr.n;
    const Eigen::Vector2d& t = fr.t;
    Eigen::Vector2d chord_force = Eigen::Vector2d::Zero();
    Eigen::Vector2d jump[2];  // u_cell1 - u_cell0 at v0 and v1
    for (int j = 0; j < 2; ++j)
      jump[j] = u.segment<2>(2 * face.node1[j]) - u.segment<2>(2 * face.node0[j]);
    for (int q = 0; q < 2; ++q) {
      const double s = rule.t[q], w = rule.weights[q] * face.length;
      const Eigen::Vector2d g = (1.0 - s) * jump[0] + s * jump[1];
      QuadraturePoint& p = face.points[q];
      const Eigen::Vector2d d = Eigen::Vector2d(g.dot(n), g.dot(t)) + p.shift;
      FacePointResponse r = face_point_response(law, d, face.closure, p.history);
      add_friction(friction_, face.closure, d[0], d[1], p.friction, r);
      const Eigen::Vector2d force = w * (r.traction[0] * n + r.traction[1] * t);
      work -= 0.5 * (p.force + force).dot(g - p.jump);
      p.opening = d;
      p.traction = r.traction;
      p.jump = g;
      p.force = force;
      add_point_force(face, q, force, f);
      if (fr.length > 0.0)
        chord_force += w * (r.traction[1] * d[0] - r.traction[0] * d[1]) / fr.length * n;
    }
    if (turning_) {
      if (!face.framed) face.chord = fr.chord;
      work -= 0.5 * (face.chord_force + chord_force).dot(fr.chord - face.chord);
      face.chord = fr.chord;
      face.chord_force = chord_force;
      face.framed = true;
      add_chord_force(face, chord_force, f);
    }
    face.end_gap = std::min(jump[0].norm(), jump[1].norm());
  }
  work_ += work;
}

void CohesiveForces::add_point_force(const Face& face, int q, const Eigen::Vector2d& force,
                                     Eigen::VectorXd& f) {
  const SegmentRule& rule = gauss2_segment();
  const double s = rule.t[q];
  // The traction resists the opening: it pulls cell1's side back and cell0's side along.
  for (int j = 0; j < 2; ++j) {
    const double share = j == 0 ? 1.0 - s : s;
    f.segment<2>(2 * face.node1[j]) -= share * force;
    f.segment<2>(2 * face.node0[j]) += share * force;
  }
}

void CohesiveForces::reassemble(Eigen::VectorXd& f) const {
  for (const Face& face : faces_) {
    if (face.released) continue;
    for (int q = 0; q < 2; ++q) add_point_force(face, q, face.points[q].force, f);
    if (turning_) add_chord_force(face, face.chord_force, f);
  }
}

bool CohesiveForces::releasable(int e) const {
  if (slot_[e] < 0) return false;
  const Face& face = faces_[slot_[e]];
  if (face.released || face.end_gap < face.length || !broken(e)) return false;
  return face.points[0].opening[0] >= 0.0 && face.points[1].opening[0] >= 0.0;
}

void CohesiveForces::release(int e) {
  if (!releasable(e))
    throw InputError("cohesive forces: edge " + std::to_string(e) +
                     " released: expected a broken face, open and apart by its length");
  faces_[slot_[e]].released = true;
  released_.push_back(e);
}

double CohesiveForces::dissipated_energy(int e) const {
  if (slot_[e] < 0) return 0.0;
  const Face& face = faces_[slot_[e]];
  const CohesiveLaw& law = law_of(slot_[e]);
  const SegmentRule& rule = gauss2_segment();
  double sum = 0.0;
  for (int q = 0; q < 2; ++q)
    sum +=
        rule.weights[q] * face.length * law.dissipated_energy(face.points[q].history.max_opening);
  return sum;
}

double CohesiveForces::dissipated_energy() const {
  double sum = 0.0;
  for (int e : edges_) sum += dissipated_energy(e);
  return sum;
}

double CohesiveForces::stored_energy() const {
  const SegmentRule& rule = gauss2_segment();
  double sum = 0.0;
  for (std::size_t slot = 0; slot < faces_.size(); ++slot)
    for (int q = 0; q < 2; ++q) {
      const Face& face = faces_[slot];
      sum += rule.weights[q] * face.length *
             (face_point_stored_energy(law_of(slot), face.points[q].opening, face.closure,
                                       face.points[q].history) +
              friction_stored_energy(friction_, face.closure, face.points[q].opening[0],
                                     face.points[q].opening[1], face.points[q].friction));
    }
  return sum;
}

double CohesiveForces::friction_dissipated_energy() const {
  const SegmentRule& rule = gauss2_segment();
  double sum = 0.0;
  for (const Face& face : faces_)
    for (int q = 0; q < 2; ++q)
      sum += rule.weights[q] * face.length * face.points[q].friction.dissipated;
  return sum;
}

Eigen::VectorXd CohesiveForces::max_openings() const {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(mesh_.num_edges());
  for (const Face& face : faces_)
    w[face.edge] = 0.5 * (face.points[0].history.max_opening + face.points[1].history.max_opening);
  return w;
}

Eigen::Vector2d CohesiveForces::point_traction(int e, int q) const {
  if (e < 0 || e >= static_cast<int>(slot_.size()) || slot_[e] < 0 || q < 0 || q > 1)
    throw InputError("cohesive forces: point " + std::to_string(q) + " of edge " +
                     std::to_string(e) + ": not a cracked edge's point");
  return faces_[slot_[e]].points[q].traction;
}

bool CohesiveForces::broken(int e) const {
  if (slot_[e] < 0) return false;
  const Face& face = faces_[slot_[e]];
  const double critical = law_of(slot_[e]).critical_opening();
  return face.points[0].history.max_opening >= critical &&
         face.points[1].history.max_opening >= critical;
}

int CohesiveForces::num_broken() const {
  int count = 0;
  for (int e : edges_) count += broken(e);
  return count;
}

void CohesiveForces::archive(StateArchive& a) {
  a.vector("cohesive.faces", faces_);
  a.vector("cohesive.edges", edges_);
  a.vector("cohesive.slot", slot_);
  a.vector("cohesive.released", released_);
  if (a.loading() && !edge_strength_.empty()) {  // each face's law follows from its edge
    face_laws_.clear();
    for (const Face& f : faces_) face_laws_.push_back(edge_law(f.edge));
  }
  a.value("cohesive.work", work_);
  a.value("cohesive.continuation_energy", continuation_energy_);
}

}  // namespace vorodg
