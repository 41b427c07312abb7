#include "dg/CohesiveInterfaces.hpp"

#include <algorithm>
#include <cmath>

#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"
#include "dg/SeriesShearLaw.hpp"
#include "fracture/FaceInsertion.hpp"
#include "fracture/FacePoint.hpp"

namespace vorodg {
namespace {

// A separated piece held only by contact would make the tangent singular: open points keep this
// fraction of eps in the tangent (not in the residual, so converged states are unchanged).
constexpr double kOpenTangentFraction = 1e-9;

/// The sticking branch's normal traction at zero normal opening under a shear opening g_t: what
/// the law's envelope leaves beside the shear traction eps g_t, sqrt(sigma_c^2 - (eps g_t /
/// beta)^2) (see CohesiveInterfaces::cohesive_law).
double sticking_strength(const CohesiveLaw& law, double eps, double gt) {
  const double beta = law.parameters().shear_factor, strength = law.parameters().strength;
  const double r = beta > 0.0 ? eps * gt / beta : 0.0;
  return std::sqrt(std::max(strength * strength - r * r, 0.0));
}

}  // namespace

CohesiveInterfaces::CohesiveInterfaces(const InterfaceOperators& ops,
                                       const InterfacePenalty& penalty, TractionKind kind,
                                       const CohesiveLaw& law, const MohrCoulomb& criterion)
    : ops_(ops), penalty_(penalty), law_(law), criterion_(criterion) {
  const auto& faces = ops.space().interfaces();
  const SegmentRule& rule = gauss2_segment();
  dofs_.reserve(faces.size());
  traction_.reserve(2 * faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    dofs_.push_back(ops.dofs(faces[i]));
    const bool constant = kind != TractionKind::point;
    for (int q = 0; q < 2; ++q)
      if (q == 0 || !constant)
        traction_.push_back(
            ops.traction(faces[i], constant ? 0.5 : rule.t[q], kind, penalty.weights(int(i))));
      else
        traction_.push_back(traction_.back());
  }
}

void CohesiveInterfaces::set_edge_strength(const std::vector<double>& factor) {
  face_laws_.clear(), face_strength_.clear();
  if (factor.empty()) return;
  const auto& faces = ops_.space().interfaces();
  const int edges = ops_.space().mesh().num_edges();
  if (static_cast<int>(factor.size()) != edges)
    throw InputError("cohesive interfaces: " + std::to_string(factor.size()) +
                     " edge strengths, expected one per mesh edge (" + std::to_string(edges) + ")");
  for (const Interface& f : faces) {
    face_strength_.push_back(factor[f.edge]);
    face_laws_.push_back(law_.with_strength_factor(factor[f.edge]));
  }
}

double CohesiveInterfaces::weight(int p) const {
  return gauss2_segment().weights[p % 2] * face(p).length;
}

InterfaceOperator CohesiveInterfaces::jump(int p) const {
  return ops_.jump(face(p), gauss2_segment().t[p % 2]);
}

Eigen::VectorXd CohesiveInterfaces::local(const Eigen::VectorXd& u, int i) const {
  return u(dofs_[i]);
}

Eigen::Matrix2d CohesiveInterfaces::frame(int i) const {
  const Eigen::Vector2d n = ops_.space().interfaces()[i].normal;
  Eigen::Matrix2d R;
  R << n.x(), n.y(), -n.y(), n.x();
  return R;
}

Eigen::Vector2d CohesiveInterfaces::opening(const Eigen::VectorXd& u, int p) const {
  return -frame(p / 2) * (jump(p) * local(u, p / 2));  // g = u_2 - u_1 = -[u]
}

Eigen::Vector2d CohesiveInterfaces::flux_traction(const Eigen::VectorXd& u, int p) const {
  // R ({sigma}n - eps [u]) with [u] = -R^T g: the cells' traction plus eps times the opening.
  return frame(p / 2) * (traction_[p] * local(u, p / 2)) + penalty_.eps(p / 2) * opening(u, p);
}

double CohesiveInterfaces::utilization(const Eigen::VectorXd& u, int p) const {
  const double strength = face_strength_.empty() ? 1.0 : face_strength_[p / 2];
  return face_utilization(criterion_, flux_traction(u, p), strength);
}

void CohesiveInterfaces::cohesive_law(const CohesiveLaw& law, double eps, const Eigen::Vector2d& g,
                                      InterfacePoint& point, Eigen::Vector2d& tau,
                                      Eigen::Matrix2d& C) const {
  const Eigen::Vector2d d = g - point.offset;
  const bool fresh = !law.intrinsic() && point.history.max_opening == 0.0;
  const double beta = law.parameters().shear_factor, strength = law.parameters().strength;
  const double shear = eps * d[1];  // the sticking branch's shear traction
  if (fresh && d[0] <= 0.0 && (std::abs(shear) < beta * strength || d[1] == 0.0)) {
    // Inserted but not yet opened: the face sticks, stiff as the coupling. Its normal traction
    // at zero opening is what the law's envelope leaves beside the shear,
    // s = sqrt(sigma_c^2 - (eps g_t / beta)^2), so that where the face opens it meets the law
    // (in series with the shear spring) in traction and in energy; the potential is
    // s(g_t) g_n + eps (g_n^2 + g_t^2) / 2. A shear past beta sigma_c slides on the law instead.
    // At the insertion point itself (no opening at all) the normal tangent is the law's
    // softening slope: the face fails because it is being loaded, so Newton should see it open,
    // not stick (with eps there it predicts no opening, then overshoots onto the softening
    // branch, and cycles).
    const double sn = sticking_strength(law, eps, d[1]);
    const double k = beta > 0.0 ? eps * eps / (beta * beta) : 0.0;  // d(r^2)/d(g_t^2)
    const double ds = -k * d[1] / sn, dds = -k * strength * strength / (sn * sn * sn);
    tau = Eigen::Vector2d(sn + eps * d[0], ds * d[0] + shear);
    C << eps, ds, ds, eps + dds * d[0];
    if (d[0] == 0.0 && d[1] == 0.0) C(0, 0) = law.envelope_slope(0.0);
    return;
  }
  if (law.intrinsic()) {  // its secant never exceeds K0: the law alone
    const auto r = law.respond(d, point.history);
    tau = r.traction;
    C = r.tangent;
  } else {  // sliding in series with the coupling's spring eps (dg/SeriesShearLaw)
    const SeriesShearResponse r = series_shear_respond(law, eps, d, point.history);
    tau = r.traction;
    C = r.tangent;
  }
  if (law.envelope(point.history.max_opening) == 0.0 && point.history.max_opening > 0.0)
    point.state = PointState::open;  // fully softened: nothing left to carry
}

void CohesiveInterfaces::face_law(int p, const Eigen::Vector2d& g, InterfacePoint& point,
                                  Eigen::Vector2d& tau, Eigen::Matrix2d& C) const {
  const double eps = penalty_.eps(p / 2);
  FacePointResponse r;
  if (point.state == PointState::cohesive)
    cohesive_law(law(p), eps, g, point, r.traction, r.tangent);
  if (point.state == PointState::open)
    r.tangent += kOpenTangentFraction * eps * Eigen::Matrix2d::Identity();
  add_closure(eps, g[0], r);  // overclosure: the contact penalty
  tau = r.traction;
  C = r.tangent;
}

Eigen::MatrixXd CohesiveInterfaces::intact_block(int p) const {
  // w (eps [u].[v] - {sigma(u)}n.[v] - {sigma(v)}n.[u]): symmetric interior penalty.
  const InterfaceOperator J = jump(p);
  const Eigen::MatrixXd JT = J.transpose() * traction_[p];
  return weight(p) * (penalty_.eps(p / 2) * J.transpose() * J - JT - JT.transpose());
}

void CohesiveInterfaces::add_intact(const BlockSink& sink) const {
  for (int i = 0; i < num_faces(); ++i) sink(i, intact_block(2 * i) + intact_block(2 * i + 1));
}

void CohesiveInterfaces::add(const Eigen::VectorXd& u, std::vector<InterfacePoint>& points,
                             Eigen::VectorXd& force, const BlockSink* tangent) const {
  for (int i = 0; i < num_faces(); ++i) {
    if (points[2 * i].state == PointState::intact && points[2 * i + 1].state == PointState::intact)
      continue;  // the base already holds both points' coupling
    const std::vector<int>& dofs = dofs_[i];
    const Eigen::VectorXd ui = u(dofs);
    const int m = static_cast<int>(dofs.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
    const Eigen::Matrix2d R = frame(i);
    for (int q = 0; q < 2; ++q) {
      const int p = 2 * i + q;
      if (points[p].state == PointState::intact) continue;
      // Take out the coupling the base holds for this point; put in the face law's work
      // w t(g).dg with dg = -R J du.
      const Eigen::MatrixXd M = intact_block(p);
      K -= M;
      f -= M * ui;
      const double w = weight(p);
      const InterfaceOperator RJ = R * jump(p);
      const Eigen::Vector2d g = -RJ * ui;
      Eigen::Vector2d tau;
      Eigen::Matrix2d C;
      face_law(p, g, points[p], tau, C);
      f -= w * RJ.transpose() * tau;
      K += w * RJ.transpose() * C * RJ;
    }
    for (int a = 0; a < m; ++a) force[dofs[a]] += f[a];
    if (tangent) (*tangent)(i, K);
  }
}

InterfaceEnergies CohesiveInterfaces::energies(const Eigen::VectorXd& u,
                                               const std::vector<InterfacePoint>& points) const {
  InterfaceEnergies e;
  for (int p = 0; p < num_points(); ++p) {
    const double w = weight(p), eps = penalty_.eps(p / 2);
    const Eigen::VectorXd ui = local(u, p / 2);
    const InterfaceOperator J = jump(p);
    if (points[p].state == PointState::intact) {
      const Eigen::Vector2d jump_u = J * ui, t = traction_[p] * ui;
      e.coupling += w * (0.5 * eps * jump_u.squaredNorm() - jump_u.dot(t));
      continue;
    }
    const Eigen::Vector2d g = opening(u, p);
    const CohesiveLaw& law_p = law(p);
    const double dmax = points[p].history.max_opening;
    if (law_p.dissipated_energy(dmax) > 0.0) e.crack_length += w;
    const Eigen::Vector2d d = g - points[p].offset;
    const double closure = closure_energy(eps, g[0]);
    if (points[p].state == PointState::cohesive && !law_p.intrinsic() && dmax == 0.0) {
      // Inserted, not yet opened: the sticking branch's potential (see cohesive_law).
      const double dn = std::min(d[0], 0.0);
      e.cohesive += w * (sticking_strength(law_p, eps, d[1]) * dn +
                         0.5 * eps * (dn * dn + d[1] * d[1]) + closure);
      continue;
    }
    if (points[p].state == PointState::open) {  // traction-free: only contact stores energy
      e.cohesive += w * closure;
      e.dissipated += w * law_p.dissipated_energy(dmax);
      continue;
    }
    const double stored = law_p.intrinsic()
                              ? law_p.stored_energy(d, points[p].history)
                              : series_shear_stored_energy(law_p, eps, d, points[p].history);
    e.cohesive += w * (stored + closure);
    e.dissipated += w * law_p.dissipated_energy(dmax);
  }
  return e;
}

}  // namespace vorodg
