// wave-bar: a bar at rest whose left end is given a velocity pulse; the pulse travels to the free
// far end at the bar speed (long sides free: uniaxial stress) or the dilatational speed (long
// sides on rollers: uniaxial strain). Measured: the pulse's arrival, hence its speed, against
// L / c (docs/dynamics.md, "Problems").
#include <cmath>
#include <numbers>

#include "core/io/StateArchive.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Format.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {
namespace {

/// The input: a (1 - cos) rise, a hold and a (1 + cos) fall, a third of `duration` each, so that
/// the velocity and its rate start and end at zero.
double pulse(double t, double amplitude, double duration) {
  const double tr = duration / 3.0;
  if (t <= 0.0 || t >= duration) return 0.0;
  if (t < tr) return amplitude * 0.5 * (1.0 - std::cos(std::numbers::pi * t / tr));
  if (t < 2.0 * tr) return amplitude;
  return amplitude * 0.5 * (1.0 + std::cos(std::numbers::pi * (t - 2.0 * tr) / tr));
}

/// Times the pulse's arrival at the far end from the mean velocity of its nodes.
class ArrivalProbe : public ProblemProbe {
 public:
  ArrivalProbe(const BodiesMesh& bodies, const CentralDifference& run, double length,
               double amplitude, double duration)
      : run_(run), length_(length), amplitude_(amplitude), duration_(duration) {
    const PolygonMesh& mesh = bodies.mesh;
    std::vector<char> on(mesh.num_vertices(), 0);
    for (const MeshEdge& e : mesh.edges())
      if (e.side == Side::right) on[e.v0] = on[e.v1] = 1;
    for (int v = 0; v < mesh.num_vertices(); ++v)
      if (on[v])
        for (int node : run.dofs().vertex_nodes(v)) far_nodes_.push_back(node);
  }

  void observe(DynamicsMeasures& m) override {
    const double now = far_end_velocity();
    // At the free far end the particle velocity doubles: the incident amplitude is reached at
    // half the doubled plateau. The input reaches half its amplitude a half rise (duration / 6)
    // after t = 0, so that is taken off to time the mid-rise's travel.
    if (std::isnan(m.arrival_time) && now / amplitude_ >= 1.0) {
      const double t = run_.time() - run_.dt() * (now - amplitude_) / (now - previous_);
      m.arrival_time = t - duration_ / 6.0;
      m.wave_speed = length_ / m.arrival_time;
      m.wave_speed_error = m.wave_speed / m.wave_speed_theory - 1.0;
    }
    previous_ = now;
  }
  void archive(StateArchive& a) override { a.value("arrival.previous", previous_); }

 private:
  double far_end_velocity() const {
    double p = 0.0, mass = 0.0;
    for (int node : far_nodes_) {
      p += run_.node_masses()[node] * run_.velocity()[2 * node];
      mass += run_.node_masses()[node];
    }
    return p / mass;
  }

  const CentralDifference& run_;
  double length_, amplitude_, duration_;
  std::vector<int> far_nodes_;  // the nodes on the right end
  double previous_ = 0.0;
};

class WaveBar : public DynamicsProblem {
 public:
  std::string name() const override { return "wave-bar"; }
  std::vector<SceneKey> keys() const override {
    return {
        key("sides", "string", "free", "free or rollers",
            "wave-bar: the long sides free (uniaxial stress, bar speed) or on rollers (uniaxial "
            "strain, dilatational speed)"),
        bounded("pulse.amplitude", "number", "1", "0 < |amplitude| <= 1e4",
                "wave-bar: the peak of the velocity prescribed on the left end, m/s", -1e4, false,
                1e4),
        bounded("pulse.duration", "number", "0.9 L / c", "0 < duration <= 1e3",
                "wave-bar: (1 - cos) rise, hold and (1 + cos) fall, a third each, s (c the "
                "expected speed, L the bar's length)",
                0.0, true, 1e3),
    };
  }
  Rectangle default_domain() const override { return Rectangle(0, 0, 1, 0.05); }
  bool prescribes_velocity() const override { return true; }

  void read(SceneKeyReader& r, ExplicitParameters& s) override {
    rollers_ = r.word(r.top(), "sides", " free rollers ") == "rollers";
    // The speed the pulse should travel at.
    speed_ = rollers_ ? s.dilatational_speed() : s.bar_speed();
    length_ = s.bodies[0].domain.width();
    SceneObject o = r.object("pulse");
    amplitude_ = r.number(o, "pulse.amplitude");
    if (amplitude_ == 0.0) o.fail_value("amplitude", "expected not 0, found 0");
    duration_ = r.number(o, "pulse.duration", 0.9 * length_ / speed_);
    o.finish();
  }

  void default_length(ExplicitParameters& s) const override { s.end = 2.0 * length_ / speed_; }
  std::string default_length_doc() const override { return "2 L / c"; }

  void add_boundaries(const PolygonMesh& mesh, CentralDifference& run) const override {
    const double amplitude = amplitude_, duration = duration_;
    run.add_velocity_boundary({mesh.side_vertices(Side::left), 0,
                               [=](double t) { return pulse(t, amplitude, duration); }});
    if (rollers_)
      for (Side side : {Side::bottom, Side::top})
        run.add_velocity_boundary({mesh.side_vertices(side), 1, [](double) { return 0.0; }});
  }

  std::unique_ptr<ProblemProbe> probe(const ExplicitParameters&, const BodiesMesh& bodies,
                                      const CentralDifference& run, int,
                                      DynamicsMeasures& m) const override {
    m.wave_speed_theory = speed_;
    m.arrival_theory = length_ / speed_;
    return std::make_unique<ArrivalProbe>(bodies, run, length_, amplitude_, duration_);
  }

  std::vector<ReportColumn> report_columns() const override {
    return {{"arrival / L/c [s]",
             [](const DynamicsMeasures& m) {
               return measure_text(m.arrival_time, 5) + " / " + measure_text(m.arrival_theory, 5);
             }},
            {"speed / theory [m/s]", [](const DynamicsMeasures& m) {
               return measure_text(m.wave_speed, 5) + " / " + measure_text(m.wave_speed_theory, 5) +
                      " (" +
                      (std::isfinite(m.wave_speed_error) ? fmt(100 * m.wave_speed_error, 3) + "%"
                                                         : "-") +
                      ")";
             }}};
  }

 private:
  bool rollers_ = false;
  double speed_ = 0.0, length_ = 0.0, amplitude_ = 0.0, duration_ = 0.0;
};

}  // namespace

std::unique_ptr<DynamicsProblem> make_wave_bar() {
  return std::make_unique<WaveBar>();
}

}  // namespace vorodg
