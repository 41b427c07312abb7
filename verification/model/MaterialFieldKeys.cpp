#include "verification/model/MaterialFieldKeys.hpp"

#include "core/schema/SceneObject.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

std::vector<SceneKey> material_field_keys() {
  const MaterialField d;
  return {
      key("material.field", "string", "none", "none, squared-exponential or matern",
          "a random material field in space: each cell's factors on E and strength are the field's "
          "means over it, and realization i is the same material on every mesh level, so the "
          "statistical report can difference the levels run by run (docs/statistics.md); none: "
          "the uniform material (or material.variation's per-cell draws)"),
      bounded("material.field_length", "number", "none (required with a field)", "0 < l <= 1e6",
              "the field's correlation length l, m", 0.0, true, 1e6),
      bounded("material.field_smoothness", "number", fmt(d.covariance.smoothness), "0 < nu <= 100",
              "matern: the smoothness nu (1/2: exponential; realizations "
              "ceil(nu) - 1 times differentiable)",
              0.0, true, 100.0),
      key("material.field_marginal", "string", "uniform", "uniform or weibull",
          "the factors' law at a point: uniform in [1 - a, 1 + a] on E and, from an independent "
          "field, on the strength; or weibull of mean 1 on the strength only (a weakest-link "
          "law)"),
      bounded("material.field_amplitude", "number", fmt(d.marginal.half_width), "0 <= a < 1",
              "uniform: the half-width a (the report's Figure 16: 0.05)", 0.0, false, 1.0, true),
      bounded("material.field_shape", "number", fmt(d.marginal.shape), "0 < k <= 1000",
              "weibull: the shape k (smaller: wider)", 0.0, true, 1e3),
      bounded("material.field_spacing", "number", "field_length / 8", "0 < spacing <= 1e6",
              "the sampling grid's spacing, m (the field is exact at its nodes, bilinear between)",
              0.0, true, 1e6),
      bounded("material.field_seed", "integer", std::to_string(d.seed), "0 <= seed <= 2147483647",
              "the field's seed; realization i draws from it and i alone, not from the mesh's seed",
              0.0, false, 2147483647.0),
  };
}

MaterialField read_material_field(SceneKeyReader& reader, SceneObject& m) {
  MaterialField f;
  const std::string kind = reader.word(m, "material.field", " none squared-exponential matern ");
  f.enabled = kind != "none";
  if (f.enabled) f.covariance.kind = covariance_kind(kind);
  if (f.enabled && !m.has("field_length"))
    m.fail_value("field_length", "expected the correlation length of material.field " + kind);
  // Its default is in words: the reader needs a number to fall back on, never used here.
  if (m.has("field_length"))
    f.covariance.length = reader.number(m, "material.field_length", f.covariance.length);
  else
    reader.note("material.field_length", "none");
  f.covariance.smoothness = reader.number(m, "material.field_smoothness");
  f.marginal.kind = marginal_kind(reader.word(m, "material.field_marginal", " uniform weibull "));
  f.marginal.half_width = reader.number(m, "material.field_amplitude");
  f.marginal.shape = reader.number(m, "material.field_shape");
  f.spacing = reader.number(m, "material.field_spacing", f.covariance.length / 8.0);
  if (!f.enabled) reader.note("material.field_spacing", "none");
  f.seed = static_cast<std::uint64_t>(reader.integer(m, "material.field_seed"));
  return f;
}

}  // namespace vorodg
