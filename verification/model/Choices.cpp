#include "verification/model/Choices.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

Choices choice_table(std::string_view text) {
  Choices out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string_view line = text.substr(at, end - at);
    at = end + 1;
    const std::size_t gap = line.find("  ");
    if (line.empty() || gap == std::string_view::npos) continue;
    const std::size_t doc = line.find_first_not_of(' ', gap);
    out.push_back({std::string(line.substr(0, gap)), std::string(line.substr(doc))});
  }
  return out;
}

const Choices& problem_choices() {
  static const Choices choices = choice_table(R"(
beam            Timoshenko's cantilever on [0, L] x [-D/2, D/2], end load P
patch           an affine field, Dirichlet data on every side
patch-mixed     an affine field, Dirichlet on the left and bottom, tractions elsewhere
patch-traction  an affine field with tractions on every side (singular: refused)
mms             a smooth manufactured field with its body force
)");
  return choices;
}

const Choices& generated_family_choices() {
  // The names are core's (family_name); the docs say which size each family takes.
  static const Choices choices = [] {
    const std::pair<MeshFamily, const char*> docs[] = {
        {MeshFamily::rcp, "randomly close-packed Voronoi (size d)"},
        {MeshFamily::hex, "regular hexagons (size h)"},
        {MeshFamily::perturbed_hex, "hexagons perturbed by r (size h)"},
        {MeshFamily::tri, "Delaunay triangles (size d)"},
        {MeshFamily::quad, "squares (size h)"}};
    Choices out;
    for (const auto& [family, doc] : docs) out.push_back({std::string(family_name(family)), doc});
    return out;
  }();
  return choices;
}

const Choices& ordering_choices() {
  static const Choices choices = choice_table(R"(
auto        made once: node-geometric (CG), else node-amd below 1e6 DOFs; node-metis otherwise
node-metis  METIS nested dissection on the node graph
node-amd    approximate minimum degree on the node graph
node-geometric  nested dissection by coordinate bisection of the node graph (CG; else node-metis)
amd         approximate minimum degree on the DOF graph
cholmod     CHOLMOD's own choice
)");
  return choices;
}

const Choices& solver_choices() {
  static const Choices choices = choice_table(R"(
auto     cholmod up to a size, amg-cg beyond (where built with hypre)
cholmod  CHOLMOD's supernodal sparse Cholesky
amg-cg   conjugate gradients preconditioned by hypre's BoomerAMG
)");
  return choices;
}

const Choices& element_choices() {
  static const Choices choices = choice_table(R"(
rk          reproducing kernel shape functions on vertex-patch weight functions
wachspress  Wachspress's rational barycentric coordinates (strictly convex cells only)
mean-value  Floater's mean value barycentric coordinates (any star-shaped cell)
vem         first-order virtual element: projection onto linears plus a scaled stabilization
)");
  return choices;
}

const Choices& plane_choices() {
  static const Choices choices = choice_table(R"(
stress  plane stress
strain  plane strain
)");
  return choices;
}

const Choices& sweep_axis_choices() {
  static const Choices choices = choice_table(R"(
nu              Poisson's ratio
kp              the DG penalty k_p
aspect          L/D of the domain
perturbation    r of the perturbed hexagons
regularization  the rcp edge-collapse threshold
h               h_avg
)");
  return choices;
}

const Choices& baseline_choices() {
  static const Choices choices = choice_table(R"(
first-nu        the same variant at the first nu
cg              the cg run on the same mesh
first-mesh      the same variant and level on the sweep's first mesh
coarsest-level  level 0 scaled by (h / h_0)^expected_rate
none            no baseline
)");
  return choices;
}

bool is_choice(const Choices& choices, const std::string& name) {
  for (const NamedChoice& c : choices)
    if (c.name == name) return true;
  return false;
}

std::string choice_list(const Choices& choices) {
  return name_list(choices);
}

std::string choice_alternatives(const Choices& choices) {
  std::string out;
  for (std::size_t i = 0; i < choices.size(); ++i) out += (i ? " | " : "") + choices[i].name;
  return out;
}

namespace {

constexpr FillOrdering kOrderings[] = {FillOrdering::automatic, FillOrdering::node_metis,
                                       FillOrdering::node_amd,  FillOrdering::node_geometric,
                                       FillOrdering::amd,       FillOrdering::cholmod_default};
constexpr LinearSolverKind kSolvers[] = {LinearSolverKind::automatic, LinearSolverKind::cholmod,
                                         LinearSolverKind::amg_cg};
constexpr ElementFamily kElements[] = {ElementFamily::rk, ElementFamily::wachspress,
                                       ElementFamily::mean_value, ElementFamily::vem};
constexpr PlaneModel kPlanes[] = {PlaneModel::stress, PlaneModel::strain};

}  // namespace

FillOrdering parse_ordering(const std::string& name) {
  return parse_enum(ordering_choices(), kOrderings, name);
}
std::string ordering_name(FillOrdering ordering) {
  return enum_name(ordering_choices(), kOrderings, ordering);
}
LinearSolverKind parse_solver(const std::string& name) {
  return parse_enum(solver_choices(), kSolvers, name);
}
std::string solver_name(LinearSolverKind kind) {
  return enum_name(solver_choices(), kSolvers, kind);
}
ElementFamily parse_element(const std::string& name) {
  return parse_enum(element_choices(), kElements, name);
}
std::string element_name(ElementFamily family) {
  return enum_name(element_choices(), kElements, family);
}
PlaneModel parse_plane(const std::string& name) {
  return parse_enum(plane_choices(), kPlanes, name);
}
std::string plane_name(PlaneModel plane) {
  return enum_name(plane_choices(), kPlanes, plane);
}
}  // namespace vorodg
