#include "dynamics/CellStress.hpp"

#include "dynamics/CorotationalFrames.hpp"

namespace vorodg {

std::vector<Eigen::Vector3d> cell_mean_stresses(
    const CentralDifference& run, const ElasticityIntegrator& integrator,
    const ElasticityIntegrator::MeanStrainOperators& strain, const std::vector<double>& stiffness) {
  const PolygonMesh& mesh = integrator.table().mesh();
  const CorotationalFrames* frames = run.force().frames();
  std::vector<Eigen::Vector3d> stresses(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    Eigen::VectorXd uc(2 * mesh.cell_size(c));
    CorotationalFrames::Turn turn;  // none for small rotations
    if (frames)
      turn = frames->local_displacements(c, run.dofs(), run.displacement(), uc);
    else
      for (int k = 0; k < mesh.cell_size(c); ++k)
        uc.segment<2>(2 * k) = run.displacement().segment<2>(2 * run.dofs().node(c, k));
    stresses[c] = CorotationalFrames::global_stress(
        turn, (stiffness.empty() ? 1.0 : stiffness[c]) * integrator.mean_stress(strain, c, uc));
  }
  return stresses;
}

}  // namespace vorodg
