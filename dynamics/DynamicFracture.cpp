#include "dynamics/DynamicFracture.hpp"

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
  clock.restart();
  const std::vector<CrackInsertion::Failure> failing =
      insertion_.failing_edges(run_.dofs(), run_.displacement(), cracked_, threads);
  times_.check += clock.seconds();
  if (failing.empty()) return 0;
  clock.restart();
  std::vector<int> edges;
  for (const CrackInsertion::Failure& f : failing) {
    cracked_[f.edge] = 1;
    connected_[f.edge] = 0;
    edges.push_back(f.edge);
    cohesive_.add_edge(f.edge);
    if (contact_) contact_->surface().expose(f.edge);
    events_.push_back({run_.step_count(), f.edge});
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

}  // namespace vorodg
