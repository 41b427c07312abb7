#pragma once
// A prescribed velocity on one direction of some mesh vertices (all nodes at each vertex, so the
// condition survives a split of the nodes). CentralDifference imposes it on the half-step
// velocities that move the displacements: u_{n+1} - u_n = dt v(t_{n+1/2}), the midpoint rule.
#include <functional>
#include <vector>

namespace vorodg {

struct VelocityBoundary {
  std::vector<int> vertices;
  int direction = 0;                       // 0: x, 1: y
  std::function<double(double)> velocity;  // of time; also evaluated at t = dt/2, 3dt/2, ...
};

}  // namespace vorodg
