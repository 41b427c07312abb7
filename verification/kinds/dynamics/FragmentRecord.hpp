#pragma once
// What a fragmentation run leaves in its record and files once it ends: its fragmentation
// measures (dynamics/problems/FragmentMeasures) and the files fragments/<run>.csv (each
// fragment's mass, cells, centre and velocity) and cracks/<run>.csv (the step at which each edge
// cracked).
#include <filesystem>
#include <string>

#include "dynamics/Fragmentation.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

/// Fills the fragmentation figures of `m` from `cracks` (of a run of `scene`) and writes
/// fragments/<id>.csv and cracks/<id>.csv under `out`.
void record_fragments(const Fragmentation& cracks, const DynamicsScene& scene,
                      const LumpedMass& mass, const std::filesystem::path& out,
                      const std::string& id, DynamicsMeasures& m);

}  // namespace vorodg
