#pragma once
// The validity check every mesh passes before an element is built on it: one precise line per
// defect (what, where, expected against found), so a user can fix an imported mesh.
#include <string>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct MeshDefect {
  enum class Kind {
    empty_mesh,
    duplicate_vertex,
    unreferenced_vertex,
    repeated_vertex_in_cell,
    clockwise_cell,
    zero_area_cell,
    self_intersecting_cell,
    not_star_shaped,
    cell_outside_domain,
    non_manifold_edge,
    inconsistent_orientation,
    boundary_edge_off_domain,
    area_mismatch,
  };
  Kind kind;
  int index;         // cell, vertex or edge the defect is about (-1 for the whole mesh)
  std::string what;  // one line
};

std::string_view defect_kind_name(MeshDefect::Kind kind);

struct MeshValidationOptions {
  /// Geometric tolerance relative to the domain size (vertices on sides, outside the domain,
  /// duplicate vertices).
  double relative_tolerance = 1e-8;
  /// Cells (and fan triangles) with area below this times h_avg^2 count as degenerate.
  double relative_min_area = 1e-12;
  /// |total cell area - domain area| / domain area allowed.
  double relative_area_tolerance = 1e-9;
  /// Stop listing after this many defects (the count is still exact).
  int max_reported = 50;
};

struct MeshValidationReport {
  std::vector<MeshDefect> defects;  // at most options.max_reported of them
  int defect_count = 0;             // all defects found
  bool ok() const { return defect_count == 0; }
  /// The defects, one per line, with a "... and N more" tail if truncated.
  std::string summary() const;
};

MeshValidationReport validate_mesh(const PolygonMesh& mesh,
                                   const MeshValidationOptions& options = {});

/// Throws InputError unless `mesh` is valid: "<what> is invalid: <first defect> (<n> defects; see
/// vorodg mesh --check)", `what` naming where the mesh came from ("mesh rcp", "mesh a.vtu").
void require_valid_mesh(const PolygonMesh& mesh, const std::string& what);

}  // namespace vorodg
