#pragma once
// The mesh families (docs/design.md "Meshes") and the one entry point that builds any of them.
// A MeshSpec is a pure description: the same spec gives a byte-identical mesh.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

enum class MeshFamily { rcp, hex, perturbed_hex, tri, quad, file };

std::string_view family_name(MeshFamily f);
/// Parses a family name; throws InputError listing the valid names.
MeshFamily parse_family(const std::string& name);

/// The generators' parameter ranges: perturbed-hex r in [0, kMaxPerturbation), rcp
/// regularization threshold in [0, kMaxRegularization) times d.
inline constexpr double kMaxPerturbation = 0.5;
inline constexpr double kMaxRegularization = 1.0;

struct MeshSpec {
  MeshFamily family = MeshFamily::rcp;
  Rectangle domain{0.0, 0.0, 4.0, 1.0};
  /// rcp, tri: minimum seed distance d. hex, perturbed-hex: seed (hexagon centre) spacing, i.e.
  /// the width across flats; adjusted so a whole number of hexagon rows fits the height.
  /// quad: target edge length.
  double size = 0.1;
  std::uint64_t seed = 1;
  /// perturbed-hex: vertices move by at most r x (their shortest edge), r in [0, 0.5).
  double perturbation = 0.3;
  /// rcp: edges shorter than this x d are collapsed (0 keeps the raw Voronoi mesh).
  double regularization = 0.1;
  /// rcp: mirror the left half's mesh about the domain's vertical mid-line, so that a straight
  /// line of edges runs along it from bottom to top (a crack line for fracture scenes).
  bool symmetric = false;
  /// symmetric: mirror only where a crack line must be made of edges: the mid-line from the
  /// bottom up to the highest line mark (a notch), and the load point at its top; the rest of
  /// the mesh stays random (docs/fracture.md "Meshes for cracks anywhere").
  bool notch_only = false;
  /// symmetric: heights at which the mid-line must have a vertex (a notch tip); the nearest
  /// vertex on the line, not a corner, moves along it to each. With notch_only, at most one.
  std::vector<double> line_marks;
  /// file: path of a .vtu mesh; its domain is `domain` if given, else its bounding box.
  std::string path;
  bool domain_given = true;
  /// Threads of the generators that use them (rcp and tri seeding); the mesh does not depend on it.
  int threads = 1;
};

/// What a generator measured on the way; written by `vorodg mesh --stats`.
struct MeshGenReport {
  std::optional<double> covered_fraction;           // rcp: whole domain
  std::optional<double> covered_fraction_interior;  // rcp: seeds >= 3d from every side
  std::map<int, int> sides_before;                  // rcp: side-count histogram, raw Voronoi
  int collapsed_edges = 0;
  int refused_collapses = 0;
  int merged_cells = 0;
  int merged_vertices = 0;  // rcp without regularization: coincident vertices merged
  int seeds = 0;
  StageTimes seconds;  // per stage
};

struct GeneratedMesh {
  PolygonMesh mesh;
  MeshGenReport report;
};

/// Builds the mesh a spec describes. Throws InputError for a bad spec (the message names the
/// parameter) and NumericalError if generation breaks down.
GeneratedMesh generate_mesh(const MeshSpec& spec);

}  // namespace vorodg
