// three-point-bend (fragmentation only): the quasi-static fracture study's notched beam
// (Petersson's, fracture/FractureProblem) loaded at a rate: pinned at the lower-left
// corner, on a roller at the lower-right one, the top vertex above the crack line pushed down at
// a prescribed speed that rises smoothly from rest. Its geometry, mesh, supports, load point and
// crack mouth are the quasi-static setup's (fracture_setup), so that one mesh realization is the
// same mesh in both studies and their curves overlay. Measured: the load-displacement and
// load-CMOD curves, the peak load and the kinetic energy's share of the work (docs/dynamics.md,
// "Three-point bend").
#include <cmath>
#include <numbers>

#include "core/meshgen/MeshFamily.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "dynamics/problems/BendCurve.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"
#include "fracture/FractureProblem.hpp"

namespace vorodg {
namespace {

/// The rise's default, in transits of the beam's depth by the dilatational wave: a velocity step
/// at the load point would send a wave of stress rho c v through the depth; a few transits of
/// rise take that front off, and are short against the beam's first bending period.
constexpr double kRiseTransits = 5.0;
/// The travel's default, a fraction of the span: 2 mm on Petersson's 2 m beam, past its peak
/// (near 0.5 mm quasi-statically) and through most of its softening tail.
constexpr double kTravelOverSpan = 1e-3;

/// The speed's share at time t: (1 - cos) / 2 over the rise, then 1.
double ramp(double t, double rise) {
  if (t <= 0.0) return 0.0;
  return t < rise ? 0.5 * (1.0 - std::cos(std::numbers::pi * t / rise)) : 1.0;
}

/// The load point's travel at time t, the integral of the speed.
double travel(double t, double speed, double rise) {
  if (t >= rise) return speed * (t - 0.5 * rise);
  return 0.5 * speed * (t - rise / std::numbers::pi * std::sin(std::numbers::pi * t / rise));
}

class ThreePointBend : public DynamicsProblem {
 public:
  std::string name() const override { return "three-point-bend"; }
  /// The quasi-static fracture study's keys where it has them (notch_depth, cracking.mode),
  /// and the load point's speed.
  std::vector<SceneKey> keys() const override {
    return {
        bounded("notch_depth", "number", "0", "0 <= notch_depth <= 1e6, below the height",
                "three-point-bend: a traction-free slit at the crack line (mid-span) from the "
                "bottom, m (as in a fracture study)",
                0.0, false, 1e6),
        key("cracking.mode", "string", "restricted", "pre-inserted or restricted",
            "three-point-bend: cohesive faces on every edge of the crack line above the notch "
            "from t = 0 (the law from zero opening), or only the crack line's edges checked by "
            "the insertion criterion (docs/dynamics.md, \"Three-point bend\")"),
        bounded("rate.speed", "number", "0.1", "0 < speed <= 1e4",
                "three-point-bend: the load point's downward speed, m/s", 0.0, true, 1e4),
        bounded("rate.rise", "number", "5 H / c_d", "0 < rise <= 1e3",
                "three-point-bend: the speed rises as (1 - cos) / 2 from 0 over this time, s (H "
                "the beam's depth, c_d the dilatational speed)",
                0.0, true, 1e3),
        bounded("rate.max_displacement", "number", "span / 1000", "0 < max_displacement <= 1e3",
                "three-point-bend: the load point's travel that ends the run where time.end and "
                "time.steps are not given, m",
                0.0, true, 1e3),
    };
  }
  bool needs_fragmentation() const override { return true; }
  bool uses_thickness() const override { return true; }
  bool prescribes_velocity() const override { return true; }
  Rectangle default_domain() const override { return Rectangle(0.0, 0.0, 2.0, 0.2); }

  void read(SceneKeyReader& r, ExplicitParameters& s) override {
    const Rectangle& d = s.bodies[0].domain;
    geometry_.problem = fracture_problem("three-point-bend");
    geometry_.domain = d;
    geometry_.line_x = 0.5 * (d.x0() + d.x1());
    geometry_.notch_depth = r.number(r.top(), "notch_depth");
    try {
      check_fracture_geometry(geometry_);
    } catch (const InputError& e) {
      throw InputError("scene " + r.top().source() + ": " + e.what());
    }
    thickness_ = s.thickness;
    SceneObject c = r.object("cracking");
    mode_ = parse_cracking_mode(r.word(c, "cracking.mode", " pre-inserted restricted "));
    c.finish();
    SceneObject o = r.object("rate");
    speed_ = r.number(o, "rate.speed");
    rise_ = r.number(o, "rate.rise", kRiseTransits * d.height() / s.dilatational_speed());
    travel_ = r.number(o, "rate.max_displacement", kTravelOverSpan * d.width());
    o.finish();
  }

  /// Until the load point has travelled rate.max_displacement.
  void default_length(ExplicitParameters& s) const override {
    if (travel_ >= travel(rise_, speed_, rise_)) {
      s.end = travel_ / speed_ + 0.5 * rise_;
      return;
    }
    double lo = 0.0, hi = rise_;  // within the rise: the travel grows monotonically
    for (int i = 0; i < 100; ++i)
      (travel(0.5 * (lo + hi), speed_, rise_) < travel_ ? lo : hi) = 0.5 * (lo + hi);
    s.end = hi;
  }
  std::string default_length_doc() const override {
    return "until the load point has travelled rate.max_displacement";
  }

  MeshSpec mesh_spec(const MeshSpec& spec) const override {
    return fracture_mesh_spec(spec, geometry_);
  }
  void check_mesh(const PolygonMesh& mesh) const override { setup(mesh); }

  CrackSites crack_sites(const PolygonMesh& mesh) const override {
    const FractureSetup s = setup(mesh);
    CrackSites sites;
    sites.eligible.assign(mesh.num_edges(), 0);
    for (int e = 0; e < mesh.num_edges(); ++e) {
      if (s.notch[e]) sites.free.push_back(e);
      if (!s.line[e]) continue;
      if (mode_ == CrackingMode::pre_inserted)
        sites.pre_inserted.push_back(e);
      else
        sites.eligible[e] = 1;
    }
    return sites;
  }

  /// The quasi-static setup's supports at rest, and its load point pushed down at the ramped speed.
  void add_boundaries(const PolygonMesh& mesh, CentralDifference& run) const override {
    const double speed = speed_, rise = rise_;
    for (const VertexConstraint& c : setup(mesh).constraints)
      run.add_velocity_boundary(
          {{c.vertex}, c.component, [=](double t) { return c.reference * speed * ramp(t, rise); }});
  }

  std::unique_ptr<ProblemProbe> probe(const ExplicitParameters&, const BodiesMesh& bodies,
                                      const CentralDifference& run, int output_every,
                                      DynamicsMeasures& m) const override {
    const FractureSetup s = setup(bodies.mesh);
    const BendGauges gauges{s.load_vertex, s.mouth.vertices.front(), geometry_.line_x, thickness_,
                            output_every};
    return std::make_unique<BendCurve>(bodies.mesh, run, gauges, m);
  }

  std::vector<ReportColumn> report_columns() const override {
    return {
        {"peak load [N]", [](const DynamicsMeasures& m) { return measure_text(m.peak_load, 5); }},
        {"displacement / CMOD at peak [m]",
         [](const DynamicsMeasures& m) {
           return measure_text(m.peak_load_displacement, 4) + " / " +
                  measure_text(m.peak_load_cmod, 4);
         }},
        {"kinetic / work at peak / end", [](const DynamicsMeasures& m) {
           return measure_text(m.kinetic_over_work_at_peak, 3) + " / " +
                  measure_text(m.kinetic_over_work_end, 3);
         }}};
  }

 private:
  /// The quasi-static setup on the mesh: the line, the notch, the supports, the load point and
  /// the mouth; throws InputError where the mesh lacks them.
  FractureSetup setup(const PolygonMesh& mesh) const {
    return fracture_setup(mesh, geometry_, mode_, thickness_);
  }

  FractureGeometry geometry_;
  CrackingMode mode_ = CrackingMode::restricted;
  double thickness_ = 1.0, speed_ = 0.0, rise_ = 0.0, travel_ = 0.0;
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_three_point_bend() {
  return std::make_unique<ThreePointBend>();
}

}  // namespace vorodg
