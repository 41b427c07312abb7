// vorodg.statistics: the report's estimators of statistical convergence between mesh levels
// (verification/report), for samples a user gathered in Python: empirical CDFs with their DKW
// band, the Kolmogorov-Smirnov and Wasserstein-1 distances with bootstrap intervals, the coupled
// differences of two levels run on the same random fields, and the sample-size planner.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "python/Bindings.hpp"
#include "verification/report/Bootstrap.hpp"
#include "verification/report/CoupledDifferences.hpp"
#include "verification/report/Distributions.hpp"
#include "verification/report/EmpiricalCdf.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"
#include "verification/report/SamplePlanner.hpp"
#include "verification/report/Wasserstein.hpp"

namespace vorodg::python {
namespace {

using Sample = std::vector<double>;

void bind_distances(py::module_& s) {
  py::class_<Interval>(s, "Interval", "An estimate with its confidence interval.")
      .def_readonly("estimate", &Interval::estimate)
      .def_readonly("low", &Interval::low)
      .def_readonly("high", &Interval::high)
      .def("contains", &Interval::contains, py::arg("x"))
      .def("__repr__", [](const Interval& i) {
        return "Interval(" + std::to_string(i.estimate) + ", [" + std::to_string(i.low) + ", " +
               std::to_string(i.high) + "])";
      });
  s.def(
      "ks_two_sample",
      [](Sample a, Sample b) {
        const KsResult r = ks_two_sample(std::move(a), std::move(b));
        return py::dict(py::arg("distance") = r.distance, py::arg("p_value") = r.p_value);
      },
      py::arg("a"), py::arg("b"),
      "Two-sample Kolmogorov-Smirnov distance and asymptotic p-value (Stephens' correction).");
  s.def("wasserstein1", &wasserstein1, py::arg("a"), py::arg("b"),
        "Wasserstein-1 distance of two samples' empirical laws, in their units.");
  const BootstrapOptions d;  // the defaults, shown in Python's signature
  s.def(
      "bootstrap_interval",
      [](const Sample& a, const Sample& b, const TwoSampleStatistic& statistic, bool paired,
         int resamples, double confidence, std::uint64_t seed) {
        const BootstrapOptions o{resamples, confidence, seed};
        return paired ? bootstrap_paired(a, b, statistic, o)
                      : bootstrap_independent(a, b, statistic, o);
      },
      py::arg("a"), py::arg("b"), py::arg("statistic"), py::arg("paired") = false,
      py::arg("resamples") = d.resamples, py::arg("confidence") = d.confidence,
      py::arg("seed") = d.seed,
      "Percentile bootstrap interval of statistic(a, b): pairs resampled together if paired, "
      "else each sample on its own. statistic may be vorodg.statistics.wasserstein1.");
}

void bind_cdf_and_intervals(py::module_& s) {
  py::class_<EmpiricalCdf>(s, "EmpiricalCdf", "A sample's empirical CDF and its DKW band.")
      .def(py::init([](Sample v) { return EmpiricalCdf(std::move(v)); }), py::arg("sample"))
      .def("__call__", &EmpiricalCdf::operator(), py::arg("x"))
      .def("__len__", &EmpiricalCdf::size)
      .def_property_readonly("sorted", &EmpiricalCdf::sorted)
      .def("quantile", &EmpiricalCdf::quantile, py::arg("p"))
      .def("dkw_half_width", &EmpiricalCdf::dkw_half_width, py::arg("confidence") = 0.95)
      .def("dkw_band", &EmpiricalCdf::dkw_band, py::arg("x"), py::arg("confidence") = 0.95);
  s.def("mean_interval", &mean_interval, py::arg("values"), py::arg("confidence") = 0.95);
  s.def("wilson_interval", &wilson_interval, py::arg("hits"), py::arg("trials"),
        py::arg("confidence") = 0.95);
  s.def(
      "coupled_differences",
      [](const Sample& coarse, const Sample& fine, double epsilon, double confidence) {
        const CoupledDifferences r = coupled_differences(coarse, fine, epsilon, confidence);
        return py::dict(py::arg("pairs") = r.pairs, py::arg("epsilon") = r.epsilon,
                        py::arg("mean_difference") = r.mean_difference,
                        py::arg("mean_absolute") = r.mean_absolute,
                        py::arg("mean_square") = r.mean_square,
                        py::arg("exceedance") = r.exceedance);
      },
      py::arg("coarse"), py::arg("fine"), py::arg("epsilon"), py::arg("confidence") = 0.95,
      "E(q_h - q_h/2), E|.|, E|.|^2 and Pr(|.| > epsilon) over realizations run on both levels.");
  s.def("normal_quantile", &normal_quantile, py::arg("p"));
  s.def("student_t_quantile", &student_t_quantile, py::arg("p"), py::arg("degrees_of_freedom"));
}

void bind_planner(py::module_& s) {
  s.def("realizations_for_ks", &realizations_for_ks, py::arg("delta"),
        py::arg("confidence") = 0.95);
  s.def("realizations_for_cdf_band", &realizations_for_cdf_band, py::arg("delta"),
        py::arg("confidence") = 0.95);
  s.def("realizations_for_mean", &realizations_for_mean, py::arg("std_dev"), py::arg("delta"),
        py::arg("confidence") = 0.95);
  s.def("realizations_for_probability", &realizations_for_probability, py::arg("p"),
        py::arg("delta"), py::arg("confidence") = 0.95);
}

}  // namespace

void bind_statistics(py::module_& m) {
  py::module_ s = m.def_submodule(
      "statistics", "Estimators of convergence in distribution, in probability and in mean.");
  bind_distances(s);
  bind_cdf_and_intervals(s);
  bind_planner(s);
}

}  // namespace vorodg::python
