#pragma once
// What a fragmentation run measures once it ends: the fragments (count, largest, the mass in
// single cells, the largest one's turn), the law's energies and balance, where the broken edges
// are (a run with a wall), the interfaces activated and the time spent in the crack checks.
#include "dynamics/ExplicitParameters.hpp"
#include "dynamics/Fragmentation.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "fracture/Fragments.hpp"

namespace vorodg {

/// Fills the fragmentation figures of `m` from `cracks` (a run of `physics`) and returns the
/// fragments it measured, for the files a study writes of them.
Fragments measure_fragments(const Fragmentation& cracks, const ExplicitParameters& physics,
                            const LumpedMass& mass, DynamicsMeasures& m);

}  // namespace vorodg
