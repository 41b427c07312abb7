// Isotropic linear elasticity (core/material/IsotropicElasticity): the plane-stress and
// plane-strain constitutive matrices against their closed forms, the Lame constants, the
// plane-strain <-> plane-stress conversion of docs/design.md (E -> E/(1-nu^2), nu -> nu/(1-nu)),
// positive definiteness up to nu -> 0.5, and rejection of E <= 0 and nu outside (-1, 0.5).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <string>

#include "core/material/IsotropicElasticity.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

Eigen::Matrix3d plane_stress(double E, double nu) {
  Eigen::Matrix3d D;
  D << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  return E / (1 - nu * nu) * D;
}

Eigen::Matrix3d plane_strain(double E, double nu) {
  Eigen::Matrix3d D;
  D << 1 - nu, nu, 0, nu, 1 - nu, 0, 0, 0, (1 - 2 * nu) / 2;
  return E / ((1 + nu) * (1 - 2 * nu)) * D;
}

double rel_diff(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(IsotropicElasticity, ClosedForms) {
  for (double E : {1.0, 210e9, 3.5e-3})
    for (double nu : {-0.9, -0.3, 0.0, 0.25, 0.3, 0.45, 0.49}) {
      const IsotropicElasticity s(E, nu, PlaneModel::stress), p(E, nu, PlaneModel::strain);
      EXPECT_EQ(s.E(), E);
      EXPECT_EQ(s.nu(), nu);
      EXPECT_EQ(s.model(), PlaneModel::stress);
      EXPECT_EQ(p.model(), PlaneModel::strain);
      EXPECT_LT(rel_diff(s.D(), plane_stress(E, nu)), 1e-15) << "E " << E << " nu " << nu;
      EXPECT_LT(rel_diff(p.D(), plane_strain(E, nu)), 1e-15) << "E " << E << " nu " << nu;
      EXPECT_NEAR(s.mu(), E / (2 * (1 + nu)), 1e-15 * E);
      EXPECT_NEAR(s.lambda(), E * nu / ((1 + nu) * (1 - 2 * nu)), 1e-15 * E / (1 - 2 * nu));
      // Shear entry is mu in both models.
      EXPECT_NEAR(s.D()(2, 2), s.mu(), 1e-15 * E);
      EXPECT_NEAR(p.D()(2, 2), p.mu(), 1e-15 * E);
      // Plane strain is plane stress with E' = E / (1 - nu^2), nu' = nu / (1 - nu) (a valid
      // plane-stress ratio only while nu' < 0.5, i.e. nu < 1/3).
      if (nu < 1.0 / 3.0) {
        const IsotropicElasticity converted(E / (1 - nu * nu), nu / (1 - nu), PlaneModel::stress);
        EXPECT_LT(rel_diff(converted.D(), p.D()), 1e-14) << "E " << E << " nu " << nu;
      }
      // Symmetric, no coupling of shear with normal strains.
      EXPECT_EQ(s.D(), s.D().transpose());
      EXPECT_EQ(p.D(), p.D().transpose());
      EXPECT_EQ(s.D()(0, 2), 0.0);
      EXPECT_EQ(p.D()(1, 2), 0.0);
    }
}

TEST(IsotropicElasticity, PositiveDefiniteUpToTheIncompressibleLimit) {
  for (double nu : {-0.999, 0.0, 0.4999, 0.5 - 1e-9, 0.5 - 1e-14})
    for (PlaneModel model : {PlaneModel::stress, PlaneModel::strain}) {
      const IsotropicElasticity m(1.0, nu, model);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m.D());
      EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << "nu " << nu;
      EXPECT_TRUE(m.D().allFinite()) << "nu " << nu;
    }
  // Plane strain stiffens without bound as nu -> 0.5; plane stress does not.
  const IsotropicElasticity strain(1.0, 0.5 - 1e-9, PlaneModel::strain);
  const IsotropicElasticity stress(1.0, 0.5 - 1e-9, PlaneModel::stress);
  EXPECT_GT(strain.D()(0, 0), 1e7);
  EXPECT_LT(stress.D()(0, 0), 2.0);
}

TEST(IsotropicElasticity, InvalidParametersThrowInputError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (PlaneModel model : {PlaneModel::stress, PlaneModel::strain}) {
    for (double E : {0.0, -0.0, -1.0, -1e-300, nan, inf, -inf})
      EXPECT_THROW(IsotropicElasticity(E, 0.3, model), InputError) << "E " << E;
    for (double nu : {0.5, 0.5000001, 0.7, -1.0, -1.5, nan, inf, -inf})
      EXPECT_THROW(IsotropicElasticity(1.0, nu, model), InputError) << "nu " << nu;
    EXPECT_NO_THROW(IsotropicElasticity(1e-300, 0.3, model));
    EXPECT_NO_THROW(IsotropicElasticity(1.0, std::nextafter(0.5, 0.0), model));
    EXPECT_NO_THROW(IsotropicElasticity(1.0, std::nextafter(-1.0, 0.0), model));
  }
  // The message names the offending parameter.
  try {
    IsotropicElasticity(1.0, 0.5, PlaneModel::strain);
    ADD_FAILURE() << "nu = 0.5 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nu"), std::string::npos) << e.what();
  }
  try {
    IsotropicElasticity(-2.0, 0.3, PlaneModel::stress);
    ADD_FAILURE() << "E = -2 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("E"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vorodg
