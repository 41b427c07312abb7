#include "dynamics/problems/DynamicsProblem.hpp"

#include <algorithm>
#include <cmath>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Format.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"

namespace vorodg {

std::vector<std::string> DynamicsProblem::own_keys() const {
  std::vector<std::string> top;
  for (const SceneKey& k : keys()) {
    const std::string name = k.name.substr(0, k.name.find('.'));
    if (std::find(top.begin(), top.end(), name) == top.end()) top.push_back(name);
  }
  return top;
}

DynamicsWall DynamicsProblem::default_wall(const ExplicitParameters& physics) const {
  const DynamicsBody& body = physics.bodies[0];
  // Thrown at the wall: the plane touches the body's leading point and faces its velocity.
  const Point ahead = hits_wall() ? Point(body.velocity.normalized()) : Point(1, 0);
  const Point centre = 0.5 * (body.domain.lo() + body.domain.hi());
  const double reach = 0.5 * (std::abs(ahead.x()) * body.domain.width() +
                              std::abs(ahead.y()) * body.domain.height());
  return {Point(centre + reach * ahead), Point(-ahead)};
}

MeshSpec DynamicsProblem::mesh_spec(const MeshSpec& spec) const {
  return spec;
}

std::unique_ptr<ProblemProbe> DynamicsProblem::probe(const ExplicitParameters&, const BodiesMesh&,
                                                     const CentralDifference&, int,
                                                     DynamicsMeasures&) const {
  return nullptr;
}

bool external_momentum(const ExplicitParameters& physics, const DynamicsProblem& problem) {
  return physics.wall || problem.prescribes_velocity() || physics.damping != 0.0 ||
         physics.gravity != Eigen::Vector2d::Zero();
}

std::vector<ReportColumn> DynamicsProblem::report_columns() const {
  return {
      {"max penetration / h_avg",
       [](const DynamicsMeasures& m) { return measure_text(m.max_penetration_over_h, 3); }},
      {"rebound / 1D estimate [m/s]",
       [](const DynamicsMeasures& m) {
         return measure_text(m.rebound_velocity, 5) + " / " + measure_text(m.rebound_estimate, 5);
       }},
      {"contact time / 2L/c_bar [s]",
       [](const DynamicsMeasures& m) {
         return measure_text(m.contact_time, 4) + " / " + measure_text(m.contact_time_estimate, 4) +
                (m.contact_ended ? "" : " (not ended)");
       }},
      {"peak wall force / rho c_bar v W [N/m]", [](const DynamicsMeasures& m) {
         return measure_text(m.peak_wall_force, 4) + " / " +
                measure_text(m.peak_wall_force_estimate, 4);
       }}};
}

std::unique_ptr<DynamicsProblem> make_dynamics_problem(const std::string& name) {
  for (std::unique_ptr<DynamicsProblem>& p : dynamics_problems())
    if (p->name() == name) return std::move(p);
  return nullptr;
}

std::string per_problem_text(const std::function<std::string(const DynamicsProblem&)>& text,
                             const std::string& separator) {
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;  // text, problems
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems()) {
    const std::string t = text(*p);
    auto g =
        std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == t; });
    if (g == groups.end()) groups.push_back({t, {}}), g = groups.end() - 1;
    g->second.push_back(p->name());
  }
  std::size_t others = groups.size();  // the largest group of two or more, said as "else"
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (groups[i].second.size() >= 2 &&
        (others == groups.size() || groups[i].second.size() > groups[others].second.size()))
      others = i;
  std::string out = "per problem: ";
  for (std::size_t i = 0, listed = 0; i < groups.size(); ++i) {
    if (i == others) continue;
    const std::vector<std::string>& names = groups[i].second;
    std::string who = names[0];
    for (std::size_t k = 1; k < names.size(); ++k)
      who += (k + 1 == names.size() ? " and " : ", ") + names[k];
    out += (listed++ ? separator : "") + who + " " + groups[i].first;
  }
  if (others < groups.size()) out += separator + "else " + groups[others].first;
  return out;
}

double extent(const Rectangle& r, const Eigen::Vector2d& direction) {
  return std::abs(direction.x()) * r.width() + std::abs(direction.y()) * r.height();
}

std::array<Eigen::Vector2d, 4> corners(const Rectangle& r) {
  return {r.lo(), Point(r.x1(), r.y0()), r.hi(), Point(r.x0(), r.y1())};
}

std::string measure_text(double x, int precision) {
  return std::isfinite(x) ? fmt(x, precision) : "";
}

}  // namespace vorodg
