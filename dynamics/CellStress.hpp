#pragma once
// The cells' mean stresses of an explicit run at its current displacement, for output: what a
// frame draws and what a user asks of a state.
#include <Eigen/Core>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "dynamics/CentralDifference.hpp"

namespace vorodg {

/// Each cell's mean stress: the integrator's mean stress from the kept mean strain operators on
/// the cell's own DOFs, times the cell's stiffness factor where the material varies (`stiffness`
/// empty: 1). Under corotational kinematics it is taken in the cell's turning frame and turned
/// back.
std::vector<Eigen::Vector3d> cell_mean_stresses(
    const CentralDifference& run, const ElasticityIntegrator& integrator,
    const ElasticityIntegrator::MeanStrainOperators& strain, const std::vector<double>& stiffness);

}  // namespace vorodg
