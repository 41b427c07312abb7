#pragma once
// A DG formulation is the set of interface terms a scheme adds to the bulk term a(u, v) and to
// the interface penalty eps int [u].[v], which every scheme has (docs/design.md, "Discontinuous
// Galerkin"). DgElasticity assembles the bulk and the penalty, factors once and, for an iterative
// scheme, back-solves once per iteration; what differs between schemes is one object of this
// interface (as MFEM makes each DG term an integrator):
//   - terms that stay on the left side, block by block per interface (SIPG's consistency and
//     symmetry terms): add_interface_block;
//   - terms that move to the right side and are lagged one iteration (the augmented Lagrangian's
//     multipliers, iterative Nitsche's average stress): interface_load, with update before each
//     iteration;
//   - the defaults it brings (penalty scaling, interface stress) and whether its matrix is
//     symmetric.
// A new scheme is one file with its class and a factory, and one line in DgFormulation.cpp's
// table (or register_dg_formulation from anywhere, as a test does).
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "interfaces/DgSpace.hpp"
#include "interfaces/InterfaceOperators.hpp"
#include "interfaces/InterfacePenalty.hpp"

namespace vorodg {

struct DgOptions;

/// What the interface terms read, owned by DgElasticity: the space, its interface operators, the
/// penalties and weights, the bulk material and the resolved options.
struct DgTermContext {
  const DgSpace& space;
  const InterfaceOperators& ops;
  const InterfacePenalty& penalty;
  const ElasticityIntegrator& integrator;
  const DgOptions& options;
  TractionKind traction;  // the stress each cell contributes to the interface average
  int threads = 1;

  /// int_F {sigma(u)}_w n . [v] on interface i, a block on its two cells' DOFs.
  Eigen::MatrixXd consistency_block(std::size_t i) const;
  int num_dofs() const { return space.num_dofs(); }
};

class DgFormulation {
 public:
  virtual ~DgFormulation() = default;

  /// How eps is scaled, and the stress the interface terms take, when the options leave them
  /// unset: h-avg (the report's) and each cell's mean stress (Eq. 29).
  virtual PenaltyScaling default_scaling() const { return PenaltyScaling::h_avg; }
  virtual TractionKind default_traction() const { return TractionKind::mean; }
  /// Whether the system matrix is symmetric (factored by Cholesky; LU otherwise).
  virtual bool symmetric() const { return true; }
  /// Whether the solve iterates (update, then a back-solve with interface_load) after the first.
  virtual bool iterative() const { return false; }
  /// Throws InputError naming an option of its own that is out of range. DgElasticity calls it;
  /// the defaults above are asked of formulations made from any options.
  virtual void check_options(const DgOptions&) const {}

  /// Adds the scheme's left-side terms on interface i to `local` (which holds the penalty block).
  virtual void add_interface_block(const DgTermContext&, std::size_t, Eigen::MatrixXd&) const {}
  /// Once after assembly, before the first solve (operators the iterations reuse).
  virtual void prepare(const DgTermContext&) {}
  /// Before each iteration after the first, with the last iterate u (all DOFs).
  virtual void update(const DgTermContext&, const Eigen::VectorXd&) {}
  /// The right-side interface terms at the last iterate u, on all DOFs.
  virtual Eigen::VectorXd interface_load(const DgTermContext& context,
                                         const Eigen::VectorXd&) const {
    return Eigen::VectorXd::Zero(context.num_dofs());
  }
  /// What to tell a user whose matrix was not positive definite, if the scheme can say why
  /// (nullopt: the factorization's own message stands).
  virtual std::optional<std::string> not_definite_hint(const DgOptions&) const {
    return std::nullopt;
  }
};

/// Makes the scheme of `options` (options.formulation), whatever its own options say
/// (check_options judges them).
using DgFormulationFactory = std::function<std::unique_ptr<DgFormulation>(const DgOptions&)>;

struct DgFormulationEntry {
  std::string name;  // as the program knows it: dg-penalty, dg-al, ...
  std::string doc;   // one line, for --help and docs/scenes.md
  DgFormulationFactory make;
};

/// Every DG formulation known, in registration order: the shipped ones first.
const std::vector<DgFormulationEntry>& dg_formulations();
/// Adds one (a name already known is refused with InputError). Returns true, so that a file can
/// register at static initialization: `const bool registered = register_dg_formulation(...)`.
bool register_dg_formulation(DgFormulationEntry entry);
/// The scheme named by options.formulation; throws InputError for an unknown name.
std::unique_ptr<DgFormulation> make_dg_formulation(const DgOptions& options);

}  // namespace vorodg
