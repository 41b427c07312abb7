#pragma once
// The two quasi-static fracture problems (docs/fracture.md "Problems"), as geometry that becomes
// a FractureSetup on a given mesh:
//   tension-bar:       u_x = 0 on the left side, u_y = 0 along the bottom (rollers), u_x = stroke
//                      on the right side; the crack line is vertical at line_x. With u_y fixed at
//                      the lower-left corner only, a bar long enough to snap back also bends: the
//                      crack opens more at one end (a bifurcation the 1D closed form ignores;
//                      docs/fracture.md). Rollers keep it on the uniform path. Its closed form:
//                      elastic up to sigma_c, then sigma = T(w) with stroke = sigma L / E' + w (E'
//                      = E in plane stress, E / (1 - nu^2) in plane strain).
//   three-point-bend:  pinned at the lower-left corner, on a roller at the lower-right one, pushed
//                      down by the stroke at the top vertex above the crack line; a traction-free
//                      notch of depth notch_depth rises from the bottom along the line.
// The crack line, the notch and the load point must be made of mesh edges and vertices: the
// setup refuses a mesh where they are not, naming what is missing.
#include <string>

#include "core/geometry/Rectangle.hpp"
#include "core/material/CohesiveLaw.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "dg/FractureSetup.hpp"

namespace vorodg {

enum class FractureProblemKind { tension_bar, three_point_bend };
/// Parses tension-bar, three-point-bend; throws InputError otherwise.
FractureProblemKind parse_fracture_problem(const std::string& name);
std::string fracture_problem_name(FractureProblemKind kind);

struct FractureGeometry {
  FractureProblemKind kind = FractureProblemKind::tension_bar;
  Rectangle domain{0.0, 0.0, 1.0, 0.1};
  double line_x = 0.5;
  double notch_depth = 0.0;
};

/// Throws InputError (one line naming the scene key) for a line outside the domain, a notch
/// outside [0, height) (or any notch on the bar).
void check_fracture_geometry(const FractureGeometry& g);

/// The mesh spec of a fracture problem's run: on a symmetric mesh the notch tip must be a vertex
/// of the line, so its height is marked (the quasi-static and the dynamic studies both mesh
/// through this, so that one realization is the same mesh in both).
MeshSpec fracture_mesh_spec(MeshSpec spec, const FractureGeometry& g);

/// The setup on `mesh`; throws InputError if the line, notch or load point is not in the mesh.
FractureSetup fracture_setup(const PolygonMesh& mesh, const FractureGeometry& g, CrackingMode mode,
                             double thickness);

/// The tension bar's closed form at crack opening w: (stroke, load in newtons).
struct BarResponse {
  double stroke, load;
};
BarResponse tension_bar_closed_form(const FractureGeometry& g, const IsotropicElasticity& material,
                                    const CohesiveLaw& law, double thickness, double opening);
/// Openings below this fraction of delta_c count as an intact bar.
inline constexpr double kIntactOpening = 1e-9;
/// How far a point of the bar's path lies from the closed form: the larger of the load's deviation
/// over the strength's load sigma_c H t and the stroke's relative deviation. An intact bar is
/// compared with its elastic line.
double tension_bar_deviation(const FractureGeometry& g, const IsotropicElasticity& material,
                             const CohesiveLaw& law, double thickness, double stroke,
                             double opening, double load);

}  // namespace vorodg
