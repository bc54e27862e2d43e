#pragma once
// Paper A's whole statistical study (the Fig. 5 analog, study/HybridStudy.h) as `semslam study hybrid` runs it on
// one layout: 50 tracks × 10 steps × 6 alphas × 2 models (600 rows; 350 runs, since a track's geometric run serves
// every alpha), sampled weights with n_s = 1000, 2 worker threads, nothing written. Two layouts: generated layout 1 (the default study's first layout,
// sim/Aliased2dLayout.h) and the hand-made parking aisle (the study's default before issue 12). One iteration per
// repetition (a study takes seconds); wall time. Counter: runs_per_s.
// Names have no '/', so the solver ratio table (RatioTable.h) ignores them.

namespace semslam::bench {

/// Registers HybridStudy_fig5_generated_layout_1 and HybridStudy_fig5_parking_aisle.
void registerHybridStudyBenchmarks();

}  // namespace semslam::bench
