// The cell-stiffness kernel (core/element/ElasticityIntegrator) on rcp, hex, perturbed-hex
// (r = 0.3, 0.4), tri and quad meshes:
//   - rigid-body modes: with the 3- and 6-point rules every cell stiffness (E = 1, nu = 0.3,
//     plane stress and strain, mean dilation off and on) is symmetric positive semidefinite with
//     exactly three eigenvalues below 1e-10 x the largest, and translations and the rotation give
//     K u = 0; with the 1-point rule the cells with spurious zero-energy modes are counted and
//     printed per family;
//   - a cell-level patch test: for a linear displacement field every strain operator returns the
//     exact strain, the mean stress is D eps, and (with the divergence correction) K u equals the
//     nodal forces of the constant stress on the cell boundary;
//   - mean dilation (B-bar): the weighted average of the volumetric row (row 0 + row 1) equals
//     the standard operator's; the B-bar volumetric strain is the cell mean at every point; B-bar
//     of a linear field is its exact strain; in plane strain near incompressibility only one
//     volumetric (lambda-sized) stiffness mode per cell remains.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

struct Config {
  PlaneModel model;
  bool mean_dilation;
  std::string name() const {
    return std::string(model == PlaneModel::stress ? "plane stress" : "plane strain") +
           (mean_dilation ? ", mean dilation" : "");
  }
};
const Config kConfigs[] = {{PlaneModel::stress, false},
                           {PlaneModel::stress, true},
                           {PlaneModel::strain, false},
                           {PlaneModel::strain, true}};

/// Rigid modes of a cell: x- and y-translation, rotation about the centroid.
Eigen::MatrixXd rigid_modes(const PolygonMesh& mesh, int c) {
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  const Point xc = mesh.cell_centroid(c);
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(2 * n, 3);
  for (int k = 0; k < n; ++k) {
    const Point d = mesh.vertex(loop[k]) - xc;
    R(2 * k, 0) = 1.0;
    R(2 * k + 1, 1) = 1.0;
    R(2 * k, 2) = -d.y();
    R(2 * k + 1, 2) = d.x();
  }
  return R;
}

struct ZeroModeCount {
  int zero = 0;            // eigenvalues below 1e-10 x largest
  double min_ratio = 0.0;  // smallest eigenvalue / largest
  double rigid_residual = 0.0;
  double asymmetry = 0.0;
};

ZeroModeCount analyse(const PolygonMesh& mesh, int c, const Eigen::MatrixXd& K) {
  ZeroModeCount out;
  out.asymmetry = (K - K.transpose()).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (K + K.transpose()),
                                                           Eigen::EigenvaluesOnly);
  const double largest = eig.eigenvalues().maxCoeff();
  for (int i = 0; i < eig.eigenvalues().size(); ++i)
    if (eig.eigenvalues()[i] < 1e-10 * largest) ++out.zero;
  out.min_ratio = eig.eigenvalues().minCoeff() / largest;
  const Eigen::MatrixXd R = rigid_modes(mesh, c);
  for (int j = 0; j < 3; ++j)
    out.rigid_residual =
        std::max(out.rigid_residual, (K * R.col(j)).norm() / (largest * R.col(j).norm()));
  return out;
}

// ---------------------------------------------------------------------------------------------
// Acceptance 7.

TEST(ElasticityIntegrator, ExactlyThreeRigidModesWithThreeAndSixPointRules) {
  for (const Family& f : kFamilies)
    for (int rule : {3, 6})
      for (bool correction : {true, false}) {
        if (rule == 6 && !correction) continue;
        const ElementTable& t = table_of(f, rule, correction);
        const PolygonMesh& mesh = t.mesh();
        for (const Config& cfg : kConfigs) {
          const ElasticityIntegrator integ(t, IsotropicElasticity(1.0, 0.3, cfg.model),
                                           cfg.mean_dilation);
          EXPECT_EQ(integ.mean_dilation(), cfg.mean_dilation);
          const std::string what = std::string(f.name) + ", " + std::to_string(rule) +
                                   "-point rule, correction " + (correction ? "on" : "off") + ", " +
                                   cfg.name();
          int bad = 0;
          Eigen::MatrixXd K;
          for (int c = 0; c < mesh.num_cells(); ++c) {
            integ.cell_matrix(c, K);
            ASSERT_EQ(K.rows(), 2 * mesh.cell_size(c));
            ASSERT_EQ(K.cols(), 2 * mesh.cell_size(c));
            const ZeroModeCount z = analyse(mesh, c, K);
            const bool ok = z.zero == 3 && z.rigid_residual < 1e-12 && z.asymmetry < 1e-14 &&
                            z.min_ratio > -1e-12;
            if (!ok && bad++ < 5)
              ADD_FAILURE() << what << ": cell " << c << " (" << mesh.cell_size(c)
                            << " sides): " << z.zero << " zero eigenvalues, rigid residual "
                            << z.rigid_residual << ", asymmetry " << z.asymmetry
                            << ", smallest eigenvalue / largest " << z.min_ratio;
          }
          EXPECT_EQ(bad, 0) << what;
        }
      }
}

TEST(ElasticityIntegrator, OnePointRuleSpuriousZeroEnergyModes) {
  for (const Family& f : kFamilies) {
    const ElementTable& t = table_of(f, 1, true);
    const PolygonMesh& mesh = t.mesh();
    for (const Config& cfg : kConfigs) {
      const ElasticityIntegrator integ(t, IsotropicElasticity(1.0, 0.3, cfg.model),
                                       cfg.mean_dilation);
      int spurious = 0, extra_modes = 0;
      Eigen::MatrixXd K;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        integ.cell_matrix(c, K);
        const ZeroModeCount z = analyse(mesh, c, K);
        // Rigid modes are zero-energy whatever the rule.
        EXPECT_LT(z.rigid_residual, 1e-12) << f.name << " cell " << c << ", " << cfg.name();
        EXPECT_GE(z.zero, 3) << f.name << " cell " << c;
        if (z.zero > 3) ++spurious, extra_modes += z.zero - 3;
      }
      std::cout << "[ zero modes ] 1-point rule, " << f.name << ", " << cfg.name() << ": "
                << spurious << " of " << mesh.num_cells()
                << " cells have spurious zero-energy modes (" << extra_modes << " modes)\n";
      ::testing::Test::RecordProperty(
          std::string("one_point_spurious_") + f.name +
              (cfg.model == PlaneModel::stress ? "_stress" : "_strain") +
              (cfg.mean_dilation ? "_bbar" : ""),
          spurious);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// A cell-level patch test.

struct LinearField {
  Eigen::Vector2d a{0.1, -0.2};
  Eigen::Matrix2d G = (Eigen::Matrix2d() << 0.3, -0.7, 0.45, 0.2).finished();
  Eigen::Vector2d at(const Point& x) const { return a + G * x; }
  Eigen::Vector3d strain() const { return {G(0, 0), G(1, 1), G(0, 1) + G(1, 0)}; }
};

Eigen::VectorXd nodal(const PolygonMesh& mesh, int c, const LinearField& u) {
  const auto loop = mesh.cell_vertices(c);
  Eigen::VectorXd out(2 * loop.size());
  for (std::size_t k = 0; k < loop.size(); ++k) out.segment<2>(2 * k) = u.at(mesh.vertex(loop[k]));
  return out;
}

TEST(ElasticityIntegrator, LinearFieldsGiveExactStrainStressAndBoundaryForces) {
  const LinearField field;
  for (const Family& f : kFamilies)
    for (int rule : {1, 3, 6}) {
      const ElementTable& t = table_of(f, rule, true);
      const PolygonMesh& mesh = t.mesh();
      for (const Config& cfg : kConfigs) {
        const IsotropicElasticity mat(1.0, 0.3, cfg.model);
        const ElasticityIntegrator integ(t, mat, cfg.mean_dilation);
        const Eigen::Vector3d eps = field.strain();
        const Eigen::Vector3d sigma = mat.D() * eps;
        const std::string what =
            std::string(f.name) + ", " + std::to_string(rule) + "-point rule, " + cfg.name();
        double worst_strain = 0, worst_stress = 0, worst_force = 0;
        StrainOperator B;
        Eigen::MatrixXd K;
        for (int c = 0; c < mesh.num_cells(); ++c) {
          const int n = mesh.cell_size(c);
          const Eigen::VectorXd u = nodal(mesh, c, field);
          for (int q = 0; q < t.num_points(c); ++q) {
            integ.strain_operator(c, q, B);
            ASSERT_EQ(B.rows(), 3);
            ASSERT_EQ(B.cols(), 2 * n);
            worst_strain = std::max(
                worst_strain, (B * u - eps).cwiseAbs().maxCoeff() / eps.cwiseAbs().maxCoeff());
          }
          worst_stress =
              std::max(worst_stress, (integ.mean_stress(c, u) - sigma).cwiseAbs().maxCoeff() /
                                         sigma.cwiseAbs().maxCoeff());
          // K u = nodal forces of the constant stress: node k gets sigma . b_k with b_k the
          // boundary integral of psi_k n.
          integ.cell_matrix(c, K);
          const Eigen::VectorXd f_int = K * u;
          const auto loop = mesh.cell_vertices(c);
          Eigen::VectorXd f_ext(2 * n);
          for (int k = 0; k < n; ++k) {
            const Point& prev = mesh.vertex(loop[(k + n - 1) % n]);
            const Point& next = mesh.vertex(loop[(k + 1) % n]);
            const Eigen::Vector2d b(0.5 * (next.y() - prev.y()), 0.5 * (prev.x() - next.x()));
            f_ext(2 * k) = sigma[0] * b.x() + sigma[2] * b.y();
            f_ext(2 * k + 1) = sigma[2] * b.x() + sigma[1] * b.y();
          }
          worst_force = std::max(
              worst_force, (f_int - f_ext).cwiseAbs().maxCoeff() / f_ext.cwiseAbs().maxCoeff());
        }
        EXPECT_LT(worst_strain, 1e-12) << what << ": strain of a linear field";
        EXPECT_LT(worst_stress, 1e-12) << what << ": mean stress of a linear field";
        EXPECT_LT(worst_force, 1e-11) << what << ": K u against the boundary forces";
      }
    }
}

// ---------------------------------------------------------------------------------------------
// Acceptance 9: mean dilation.

TEST(ElasticityIntegrator, MeanDilationKeepsTheAverageVolumetricOperator) {
  for (const Family& f : kFamilies)
    for (PlaneModel model : {PlaneModel::stress, PlaneModel::strain}) {
      const ElementTable& t = table_of(f, 3, true);
      const PolygonMesh& mesh = t.mesh();
      const IsotropicElasticity mat(1.0, 0.3, model);
      const ElasticityIntegrator standard(t, mat, false), bbar(t, mat, true);
      double worst = 0.0;
      StrainOperator B, Bb;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        const int n = mesh.cell_size(c);
        Eigen::RowVectorXd avg = Eigen::RowVectorXd::Zero(2 * n), avg_b = avg;
        double area = 0.0;
        for (int q = 0; q < t.num_points(c); ++q) {
          standard.strain_operator(c, q, B);
          bbar.strain_operator(c, q, Bb);
          avg += t.weight(c, q) * (B.row(0) + B.row(1));
          avg_b += t.weight(c, q) * (Bb.row(0) + Bb.row(1));
          area += t.weight(c, q);
          // The shear row is untouched.
          EXPECT_EQ(B.row(2), Bb.row(2)) << f.name << " cell " << c;
        }
        const double h = std::sqrt(mesh.cell_area(c));
        worst = std::max(worst, (avg_b - avg).cwiseAbs().maxCoeff() * h / area);
      }
      EXPECT_LT(worst, 1e-12) << f.name
                              << (model == PlaneModel::stress ? " plane stress" : " plane strain");
    }
}

TEST(ElasticityIntegrator, MeanDilationVolumetricStrainIsTheCellMeanAtEveryPoint) {
  // B-bar replaces the volumetric part of the strain by its cell mean (docs/design.md): in-plane
  // volumetric strain eps_xx + eps_yy of the B-bar operator (row 0 + row 1) must be the same at
  // every quadrature point of the cell, equal to the standard operator's cell average. In plane
  // strain eps_zz = 0, so eps_xx + eps_yy is the whole volumetric strain.
  for (const Family& f : kFamilies)
    for (PlaneModel model : {PlaneModel::stress, PlaneModel::strain}) {
      const ElementTable& t = table_of(f, 3, true);
      const PolygonMesh& mesh = t.mesh();
      const IsotropicElasticity mat(1.0, 0.3, model);
      const ElasticityIntegrator standard(t, mat, false), bbar(t, mat, true);
      double worst = 0.0;
      int worst_cell = -1;
      StrainOperator B, Bb;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        const int n = mesh.cell_size(c);
        Eigen::RowVectorXd avg = Eigen::RowVectorXd::Zero(2 * n);
        double area = 0.0;
        for (int q = 0; q < t.num_points(c); ++q) {
          standard.strain_operator(c, q, B);
          avg += t.weight(c, q) * (B.row(0) + B.row(1));
          area += t.weight(c, q);
        }
        avg /= area;
        const double h = std::sqrt(mesh.cell_area(c));
        for (int q = 0; q < t.num_points(c); ++q) {
          bbar.strain_operator(c, q, Bb);
          const double d = (Bb.row(0) + Bb.row(1) - avg).cwiseAbs().maxCoeff() * h;
          if (d > worst) worst = d, worst_cell = c;
        }
      }
      EXPECT_LT(worst, 1e-12) << f.name
                              << (model == PlaneModel::stress ? " plane stress" : " plane strain")
                              << ": B-bar volumetric row differs from the cell mean by " << worst
                              << " (x h) in cell " << worst_cell;
    }
}

TEST(ElasticityIntegrator, MeanDilationLeavesOneVolumetricModeNearIncompressibility) {
  // Plane strain, nu -> 0.5: lambda ~ 1.7e7 E. Without mean dilation the pointwise divergence
  // is penalised at every quadrature point (many lambda-sized eigenvalues: locking); with it only
  // the cell-mean dilation is, so exactly one eigenvalue per cell is lambda-sized.
  for (const Family& f : kFamilies) {
    const ElementTable& t = table_of(f, 3, true);
    const PolygonMesh& mesh = t.mesh();
    const IsotropicElasticity mat(1.0, 0.5 - 1e-8, PlaneModel::strain);
    for (bool mean_dilation : {false, true}) {
      const ElasticityIntegrator integ(t, mat, mean_dilation);
      int cells_not_one = 0, max_stiff = 0;
      Eigen::MatrixXd K;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        integ.cell_matrix(c, K);
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, Eigen::EigenvaluesOnly);
        int stiff = 0;
        for (int i = 0; i < eig.eigenvalues().size(); ++i)
          if (eig.eigenvalues()[i] > 1e4 * mat.mu()) ++stiff;
        max_stiff = std::max(max_stiff, stiff);
        if (stiff != 1) ++cells_not_one;
      }
      std::cout << "[ locking ] " << f.name << ", plane strain nu = 0.5 - 1e-8, mean dilation "
                << (mean_dilation ? "on" : "off") << ": " << cells_not_one << " of "
                << mesh.num_cells() << " cells have != 1 lambda-sized eigenvalue (max " << max_stiff
                << ")\n";
      if (mean_dilation) {
        EXPECT_EQ(cells_not_one, 0) << f.name << ": B-bar should leave one volumetric mode";
      }
    }
  }
}

}  // namespace
}  // namespace vorodg
