#include "core/problem/AffineField.hpp"

namespace vorodg {

namespace {
std::array<BoundaryKind, 4> sides_for(AffineField::Supports supports) {
  constexpr auto D = BoundaryKind::dirichlet, T = BoundaryKind::traction;
  switch (supports) {
    case AffineField::Supports::dirichlet: return {D, D, D, D};
    case AffineField::Supports::mixed: return {D, T, D, T};  // left, right, bottom, top
    default: return {T, T, T, T};
  }
}
}  // namespace

AffineField::AffineField(const IsotropicElasticity& material, Supports supports)
    : ExactSolution(material, sides_for(supports)), supports_(supports) {}

std::string AffineField::name() const {
  switch (supports_) {
    case Supports::dirichlet: return "patch";
    case Supports::mixed: return "patch-mixed";
    default: return "patch-traction";
  }
}

}  // namespace vorodg
