#pragma once
// The `tradeoff` block of a trade-off scene (docs/scenes.md): when a configuration may stand on
// the front, which levels are timed, which errors the recommendation is given for and how the
// recommendation is checked. The defaults, a rate within 12.5% of the expected one and runs of
// at least half a second, are argued in docs/tradeoff.md.
#include <vector>

namespace vorodg {

class SceneObject;

struct TradeoffSettings {
  /// Admission: each least-squares rate within this fraction of its expected value (L2 2,
  /// energy 1: first-order elements).
  double rate_tolerance = 0.125;
  /// Levels whose median run takes at least this many seconds are timed: only they enter the
  /// error-cost fits and the front (shorter runs are as noisy as they are long).
  double min_seconds = 0.5;
  /// L2 errors the recommendation is given for; empty: three decades, the smallest the power of
  /// ten at or below the best error reached at the finest level.
  std::vector<double> targets;
  /// Run the recommendation for the smallest target once more, at the predicted mesh size, and
  /// compare its time and error with the prediction.
  bool verify = true;
  int verification_realizations = 4;  // runs of that check: a median, at the study's load
};

/// Reads the block (every key optional); fails naming the key on a bad value.
TradeoffSettings read_tradeoff_settings(SceneObject& block);

}  // namespace vorodg
