#pragma once
// The quasi-static fracture problems (docs/fracture.md "Problems"), each a FractureProblem that
// turns a geometry into a FractureSetup on a given mesh (its gauges and its supports), with its
// closed form where it has one. The shipped two, one file each, are listed once in
// FractureProblem.cpp's table (a new one is its file and one line there):
//   tension-bar (TensionBar.cpp):       pulled apart across a vertical crack line;
//   three-point-bend (ThreePointBendBeam.cpp): simply supported, pushed down above the crack line,
//                                       a traction-free notch rising from the bottom.
// The crack line, the notch and the load point must be made of mesh edges and vertices: the
// setup refuses a mesh where they are not, naming what is missing.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "fracture/CohesiveLaw.hpp"
#include "fracture/FractureSetup.hpp"

namespace vorodg {

class FractureProblem;

struct FractureGeometry {
  std::shared_ptr<const FractureProblem> problem;
  Rectangle domain{0.0, 0.0, 1.0, 0.1};
  double line_x = 0.5;
  double notch_depth = 0.0;
};

class FractureProblem {
 public:
  virtual ~FractureProblem() = default;
  /// The name a scene gives as `problem`.
  virtual std::string name() const = 0;
  /// Whether the geometry may have a notch (notch_depth > 0).
  virtual bool takes_notch() const { return true; }
  /// The load point (if any) and the crack-mouth gauge; throws InputError where the mesh has no
  /// vertex where one must be.
  virtual void find_gauges(const PolygonMesh& mesh, const FractureGeometry& g,
                           FractureSetup& s) const = 0;
  /// The supports and the prescribed stroke (a constraint of value 1 or -1 scales with it).
  virtual void add_constraints(const PolygonMesh& mesh, const FractureGeometry& g, double tol,
                               FractureSetup& s) const = 0;
  /// How far a point of the path (stroke, crack opening, load) lies from the problem's closed
  /// form, relative; nullopt where it has none.
  virtual std::optional<double> closed_form_deviation(const FractureGeometry&,
                                                      const IsotropicElasticity&,
                                                      const CohesiveLaw&, double /*thickness*/,
                                                      double /*stroke*/, double /*opening*/,
                                                      double /*load*/) const {
    return std::nullopt;
  }
};

/// Every fracture problem, in the order docs and messages list them.
const std::vector<std::shared_ptr<const FractureProblem>>& fracture_problems();
/// The problem called `name`; throws InputError for an unknown name.
std::shared_ptr<const FractureProblem> fracture_problem(const std::string& name);
/// "tension-bar or three-point-bend": the names, for messages and the key table.
std::string fracture_problem_list();
/// " tension-bar three-point-bend ": the names, each with a space either side (scene readers).
std::string fracture_problem_words();
/// The vertex at p (within the mesh's tagging tolerance), or -1.
int mesh_vertex_at(const PolygonMesh& mesh, const Point& p);

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

}  // namespace vorodg
