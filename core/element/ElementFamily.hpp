#pragma once
// Which shape functions a cell carries. Every family fills the same element table (values and
// gradients at the fan quadrature points, values on the edges linear between the vertices), so
// CG, DG, fracture and dynamics use any of them without knowing which.
namespace vorodg {

enum class ElementFamily {
  rk,          // reproducing kernel with vertex-patch weight functions (the default)
  wachspress,  // Wachspress's rational coordinates: strictly convex cells only
  mean_value,  // Floater's mean value coordinates: any star-shaped cell
  vem,         // lowest-order virtual element: the projection onto linears plus a stabilization
};

}  // namespace vorodg
