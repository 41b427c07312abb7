#include "dynamics/DynamicFracture.hpp"

#include <algorithm>

#include "core/io/StateArchive.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

DynamicFracture::DynamicFracture(const PolygonMesh& mesh, CentralDifference& run,
                                 CohesiveForces& cohesive, const CrackInsertion& insertion,
                                 ContactForces* contact)
    : mesh_(mesh),
      run_(run),
      cohesive_(cohesive),
      insertion_(insertion),
      contact_(contact),
      cracked_(mesh.num_edges(), 0),
      connected_(mesh.num_edges(), 1) {
  for (int e : cohesive.edges()) cracked_[e] = 1, connected_[e] = 0;
  run_.set_cohesive(cohesive_);
}

int DynamicFracture::step(int threads) {
  Stopwatch clock;
  run_.step();
  release_faces();
  times_.integrator += clock.seconds();
  if (activation_) return activate(threads);
  clock.restart();
  // The step has just computed the internal force at this u: its cells' local displacements
  // are the check's (no need to turn every cell again).
  const std::vector<CrackInsertion::Failure> failing = insertion_.failing_edges(
      run_.dofs(), run_.displacement(), cracked_, threads, run_.force().local_displacements());
  times_.check += clock.seconds();
  if (failing.empty()) return 0;
  clock.restart();
  std::vector<int> edges;
  for (const CrackInsertion::Failure& f : failing) {
    crack(f.edge);
    edges.push_back(f.edge);
    cohesive_.add_edge(f.edge);
  }
  // The first rebuild starts from the edge set alone, whatever map the run began with; after
  // it only the classes at the new cracks' vertices change (SplitDofMap::disconnect).
  if (!split_yet_) {
    run_.remap(SplitDofMap(mesh_, connected_));
    split_yet_ = true;
  } else {
    run_.disconnect(connected_, edges);
  }
  times_.rebuild += clock.seconds();
  return static_cast<int>(failing.size());
}

void DynamicFracture::cut(std::span<const int> edges) {
  for (int e : edges) connected_[e] = 0;
}

void DynamicFracture::crack(int edge) {
  cracked_[edge] = 1;
  connected_[edge] = 0;
  if (contact_) contact_->surface().expose(edge);
  events_.push_back({run_.step_count(), edge});
}

int DynamicFracture::activate(int threads) {
  Stopwatch clock;
  const std::vector<InterfaceActivation::Failure> failing =
      activation_->failing(threads);  // the fluxes of the step's force evaluation
  times_.check += clock.seconds();
  if (failing.empty()) return 0;
  clock.restart();
  activation_->activate(failing, run_.displacement(), cohesive_);
  std::vector<int> vertices;
  for (const InterfaceActivation::Failure& f : failing) {
    crack(f.edge);
    vertices.push_back(mesh_.edge(f.edge).v0);
    vertices.push_back(mesh_.edge(f.edge).v1);
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  cohesive_.rebind(run_.dofs(), vertices);
  run_.refresh_interfaces();
  times_.rebuild += clock.seconds();
  return static_cast<int>(failing.size());
}

void DynamicFracture::release_faces() {
  if (!contact_ || !contact_->surfaces()) return;
  for (int e : cohesive_.edges()) {
    if (!cohesive_.releasable(e)) continue;
    const MeshEdge& edge = mesh_.edge(e);
    if (contact_->overlapping(edge.cell0, edge.cell1)) continue;
    cohesive_.release(e);
    contact_->surface().release(e);
  }
}

CrackState DynamicFracture::crack_state() const {
  return CrackState(mesh_, cracked_, cohesive_.max_openings());
}

CrackState DynamicFracture::broken_state() const {
  std::vector<char> broken(mesh_.num_edges(), 0);
  for (int e : cohesive_.edges()) broken[e] = cohesive_.broken(e);
  return CrackState(mesh_, broken);
}

void DynamicFracture::archive(StateArchive& a) {
  a.vector("fracture.cracked", cracked_);
  a.vector("fracture.connected", connected_);
  a.value("fracture.split_yet", split_yet_);
  a.vector("fracture.events", events_);
}

}  // namespace vorodg
