// The keys a fragmentation study adds to a dynamics scene (docs/fragmentation.md): the cohesive
// law and the insertion criterion. A dynamics study refuses them.
#include "core/util/Errors.hpp"
#include "fracture/SofteningLaws.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"

namespace vorodg {

void DynamicsSceneReader::read_fracture() {
  for (const char* key : {"cohesive", "criterion"})
    if (!s_.fragmentation && top_.has(key)) top_.fail_value(key, "only in a fragmentation study");
  if (!s_.fragmentation) return;
  SceneObject c = object("cohesive");
  CohesiveParameters& law = s_.cohesive;
  law.shape = word(c, "cohesive.law", softening_law_words());
  law.strength = number(c, "cohesive.strength");
  law.fracture_energy = number(c, "cohesive.fracture_energy");
  law.shear_factor = number(c, "cohesive.shear_factor");
  s_.stiffness_factor = number(c, "cohesive.initial_stiffness");
  SceneObject m = object("criterion");
  s_.criterion.cohesion = number(m, "criterion.cohesion", law.strength);
  s_.criterion.friction = number(m, "criterion.friction");
  s_.criterion.tensile_cutoff = number(m, "criterion.tensile_cutoff", law.strength);
  m.finish();
  // The faces are the material's failure planes: by default they slide with its friction.
  s_.face_friction = number(c, "cohesive.face_friction", s_.criterion.friction);
  // A fraction of K0, or "interface": each face keeps its interface's penalty (dg only).
  if (c.has("closure_stiffness") && c.at("closure_stiffness").is_string()) {
    word(c, "cohesive.closure_stiffness", " interface ");
    if (!s_.dg_interfaces)
      c.fail_value("closure_stiffness",
                   "'interface' with interfaces insertion: expected a number (only interfaces dg "
                   "have a penalty)");
    s_.interface_closure = true;
  } else {
    s_.closure_fraction = number(c, "cohesive.closure_stiffness");
  }
  s_.turning_faces = flag(c, "cohesive.turning_frames");
  if (s_.turning_faces && !s_.corotational)
    c.fail_value("turning_frames", "true with kinematics small: expected corotational");
  c.finish();
}

}  // namespace vorodg
