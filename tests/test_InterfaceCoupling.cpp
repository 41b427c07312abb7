// Interfaces coupled from the start in explicit dynamics (dynamics/InterfaceCoupling): the
// symmetric interior-penalty terms of the quasi-static DG solver (coercive penalty, fan
// tractions) as forces on a fully split rcp map, checked without its own assembly:
//   - the patch test: a linear displacement field (no jumps) is in equilibrium in the interior,
//     cells and interfaces together, to round-off (the interface terms are consistent);
//   - the force loop's factored form is -K u with the SIPG blocks, and its energy 1/2 u.K u;
//   - the forces are linear and symmetric (v.f(u) = u.f(v)) and derive from the energy
//     1/2 u.K u = -1/2 u.f(u);
//   - a jump alone is resisted: pulling one cell's copy of a vertex away from its neighbours'
//     gives a force against the pull;
//   - the penalty is the quasi-static solver's (eps > 0 on every interface), and the Gershgorin
//     bound of M^-1 K_I is at least its Rayleigh quotient on a random field;
//   - in the integrator, at 0.9 of the step the cells' and the interfaces' bounds allow: a free
//     body set vibrating keeps its energy (coupling energy booked as elastic) to round-off over
//     1e4 steps, and its momentum; and its motion follows the continuous map's (the jumps stay
//     a small fraction of the displacements).
#include "dynamics/InterfaceCoupling.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/util/Errors.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/InternalForce.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

struct Coupled {
  DynamicsModel model{mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 0.5), 0.1),
                      IsotropicElasticity(1.0, 0.3, PlaneModel::strain), 1.0};
  SplitDofMap dofs = SplitDofMap::discontinuous(model.mesh);
  InterfaceCoupling coupling{model.table, model.integrator, model.matrices, dofs};

  /// Node displacements of the field u(x) = G x + c on every cell's copy of each vertex.
  Eigen::VectorXd linear(const Eigen::Matrix2d& G, const Eigen::Vector2d& c) const {
    Eigen::VectorXd u(dofs.num_dofs());
    for (int cell = 0; cell < model.mesh.num_cells(); ++cell)
      for (int k = 0; k < model.mesh.cell_size(cell); ++k)
        u.segment<2>(2 * dofs.node(cell, k)) =
            G * model.mesh.vertex(model.mesh.cell_vertices(cell)[k]) + c;
    return u;
  }
};

TEST(InterfaceCoupling, ALinearFieldIsInEquilibriumInTheInterior) {
  const Coupled m;
  ASSERT_GT(m.coupling.num_interfaces(), 50);
  Eigen::Matrix2d G;
  G << 1e-3, 2e-4, -5e-4, 3e-4;
  const Eigen::VectorXd u = m.linear(G, Eigen::Vector2d(0.1, -0.2));
  InternalForce cells(m.model.mesh, m.model.matrices);
  Eigen::VectorXd f;
  cells.compute(m.dofs, u, f, 1);
  const double scale = f.cwiseAbs().maxCoeff();
  f = -f;  // InternalForce gives K u; the force on the nodes is -K u
  m.coupling.add_forces(u, f);
  double worst = 0.0;
  for (int i = 0; i < m.dofs.num_nodes(); ++i) {
    bool boundary = false;
    for (int p : m.dofs.node_pairs(i)) {
      const int v = m.model.mesh.cell_vertex_list()[p];
      for (int c : m.model.mesh.vertex_cells(v))
        for (int e : m.model.mesh.cell_edges(c))
          if (m.model.mesh.edge(e).on_boundary() &&
              (m.model.mesh.edge(e).v0 == v || m.model.mesh.edge(e).v1 == v))
            boundary = true;
    }
    if (!boundary) worst = std::max(worst, f.segment<2>(2 * i).norm());
  }
  std::printf("linear field: largest interior node force %.2e of the cells' force scale %.2e\n",
              worst, scale);
  EXPECT_LT(worst, 1e-10 * scale);
}

TEST(InterfaceCoupling, ForcesAreSymmetricAndDeriveFromTheEnergy) {
  const Coupled m;
  const Eigen::VectorXd u = random_vector(m.dofs.num_dofs(), 1e-3, 3);
  const Eigen::VectorXd v = random_vector(m.dofs.num_dofs(), 1e-3, 4);
  Eigen::VectorXd fu = Eigen::VectorXd::Zero(u.size()), fv = Eigen::VectorXd::Zero(u.size());
  const double energy = m.coupling.add_forces(u, fu);
  m.coupling.add_forces(v, fv);
  const double scale = fu.norm() * v.norm();
  EXPECT_NEAR(v.dot(fu), u.dot(fv), 1e-12 * scale);
  EXPECT_NEAR(energy, -0.5 * u.dot(fu), 1e-12 * std::abs(u.dot(fu)));
  Eigen::VectorXd f2 = Eigen::VectorXd::Zero(u.size());
  m.coupling.add_forces(2.0 * u, f2);
  EXPECT_LT((f2 - 2.0 * fu).norm(), 1e-12 * fu.norm());
}

TEST(InterfaceCoupling, TheFactoredForceIsTheSipgBlocks) {
  // The force loop uses the blocks' factors (flux and jump at the Gauss points): it must be
  // -K u with K the quasi-static solver's SIPG blocks, and its energy 1/2 u.K u.
  const Coupled m;
  const Eigen::VectorXd u = random_vector(m.dofs.num_dofs(), 1e-3, 5);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size()), reference = f;
  const double energy = m.coupling.add_forces(u, f);
  double reference_energy = 0.0;
  for (int i = 0; i < m.coupling.num_interfaces(); ++i) {
    const std::vector<int>& d = m.coupling.block_dofs(i);
    Eigen::VectorXd x(d.size());
    for (std::size_t k = 0; k < d.size(); ++k) x[k] = u[d[k]];
    const Eigen::VectorXd Kx = m.coupling.block(i) * x;
    reference_energy += 0.5 * x.dot(Kx);
    for (std::size_t k = 0; k < d.size(); ++k) reference[d[k]] -= Kx[k];
  }
  EXPECT_LT((f - reference).norm(), 1e-12 * reference.norm());
  EXPECT_NEAR(energy, reference_energy, 1e-12 * std::abs(reference_energy));
}

TEST(InterfaceCoupling, AJumpIsResisted) {
  const Coupled m;
  for (int i = 0; i < m.coupling.num_interfaces(); ++i) EXPECT_GT(m.coupling.penalty(i), 0.0);
  // One cell moved rigidly away from everything else: its copies' forces pull it back.
  const int cell = m.model.mesh.num_cells() / 2;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.dofs.num_dofs());
  for (int k = 0; k < m.model.mesh.cell_size(cell); ++k)
    u.segment<2>(2 * m.dofs.node(cell, k)) = Eigen::Vector2d(1e-4, 0.0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size());
  const double energy = m.coupling.add_forces(u, f);
  Eigen::Vector2d on_cell = Eigen::Vector2d::Zero();
  for (int k = 0; k < m.model.mesh.cell_size(cell); ++k)
    on_cell += f.segment<2>(2 * m.dofs.node(cell, k));
  EXPECT_LT(on_cell.x(), 0.0);
  EXPECT_GT(energy, 0.0);
  // The bound holds on a random field: u.K u / u.M u <= the Gershgorin bound.
  const Eigen::VectorXd masses = m.model.mass.node_masses(m.dofs);
  const Eigen::VectorXd w = random_vector(m.dofs.num_dofs(), 1.0, 9);
  Eigen::VectorXd fw = Eigen::VectorXd::Zero(w.size());
  const double quotient_top = 2.0 * m.coupling.add_forces(w, fw);
  double mass_norm = 0.0;
  for (int i = 0; i < m.dofs.num_nodes(); ++i)
    mass_norm += masses[i] * w.segment<2>(2 * i).squaredNorm();
  EXPECT_LE(std::abs(quotient_top) / mass_norm, m.coupling.eigenvalue_bound(masses));
  EXPECT_THROW(InterfaceCoupling(m.model.table, m.model.integrator, m.model.matrices, m.dofs, 0.0),
               InputError);
}

TEST(InterfaceCoupling, TheIntegratorKeepsTheCoupledBodysEnergy) {
  const Coupled m;
  const Eigen::VectorXd masses = m.model.mass.node_masses(m.dofs);
  const double lambda =
      std::pow(2.0 / m.model.limit.critical(), 2) + m.coupling.eigenvalue_bound(masses);
  const double dt = 0.9 * 2.0 / std::sqrt(lambda);
  CentralDifference run(m.model.mesh, m.model.mass, InternalForce(m.model.mesh, m.model.matrices),
                        m.dofs, dt);
  run.set_interface_coupling(m.coupling);
  Eigen::Matrix2d G;  // a dilation and a shear: the body rings
  G << 1.0, 0.3, 0.3, -0.5;
  const Eigen::VectorXd v0 = 1e-3 * m.linear(G, Eigen::Vector2d(-0.5, -0.25));
  run.initialize(Eigen::VectorXd::Zero(v0.size()), v0);
  const StepRecord start = run.record();
  double worst = 0.0, largest_jump = 0.0, largest_u = 0.0;
  for (int s = 0; s < 10000; ++s) {
    run.step();
    worst = std::max(worst, std::abs(run.record().balance() - start.balance()));
  }
  for (const Interface& f : m.coupling.space().interfaces())
    for (int j = 0; j < 2; ++j) {
      const int a = f.dof_v0[j], b = f.dof_v1[j];
      largest_u = std::max({largest_u, run.displacement().segment<2>(a).norm(),
                            run.displacement().segment<2>(b).norm()});
    }
  for (const Interface& f : m.coupling.space().interfaces())
    largest_jump = std::max(largest_jump, (run.displacement().segment<2>(f.dof_v0[0]) -
                                           run.displacement().segment<2>(f.dof_v0[1]))
                                              .norm());
  // The price in steps: Lanczos on the coupled system against the continuous map's.
  InternalForce cells(m.model.mesh, m.model.matrices);
  const SplitDofMap continuous = SplitDofMap::continuous(m.model.mesh);
  const double coupled_step =
      GlobalTimeStep(cells, m.dofs, masses, m.model.limit, {}, &m.coupling).critical();
  const double continuous_step =
      GlobalTimeStep(cells, continuous, m.model.mass.node_masses(continuous), m.model.limit)
          .critical();
  std::printf("critical steps: coupled (Lanczos) %.3e, bound %.3e; continuous map %.3e\n",
              coupled_step, dt / 0.9, continuous_step);
  EXPECT_GE(coupled_step, dt / 0.9 * (1.0 - 1e-12));  // never below what the bound gives
  std::printf(
      "coupled free body: dt %.3e (cells alone %.3e), balance drift %.1e of %.3e, "
      "largest jump %.2e of the largest displacement %.2e\n",
      dt, 0.9 * m.model.limit.critical(), worst, start.kinetic, largest_jump, largest_u);
  EXPECT_LT(worst, 1e-11 * start.kinetic);  // round-off of 1e4 steps (measured 2.4e-12)
  double scale = 0.0;                       // sum of m |v(0)|
  for (int i = 0; i < m.dofs.num_nodes(); ++i) scale += masses[i] * v0.segment<2>(2 * i).norm();
  EXPECT_LT((run.record().momentum - start.momentum).norm(), 1e-12 * scale);
  EXPECT_LT(largest_jump, 0.05 * largest_u);
  EXPECT_GT(run.record().elastic, 0.0);
}

}  // namespace
}  // namespace vorodg
