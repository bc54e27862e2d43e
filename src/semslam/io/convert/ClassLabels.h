#pragma once
// Class labels for converted datasets: the class of a landmark is its id mod M, and each detection's label is a
// draw from the categorical confusion model (models/CategoricalClassifierModel.h) for its true class.
//
// With M ≥ 2 the header becomes semantic "label", classifier categorical with misclassification p, and every
// detection gets a label, drawn from one std::mt19937 seeded with `seed`, in a fixed order: step by step, and within
// a step in detection order; every draw consumes exactly two engine outputs (Sampling.h's uniform01), so the same
// seed gives the same labels on every platform and a log's first N steps get the same labels whatever follows them.
//   - a detection of landmark l:            label ~ row (l mod M) of C = (1 − p) I + p/(M − 1)(11ᵀ − I);
//   - clutter (truth "not a landmark") or a detection of unknown truth (absent, or kUnknownTruth), ClutterLabels::Uniform: label uniform on
//     [0, M) (clutter has no class: a uniform label carries no information about it, as a null hypothesis expects);
//   - clutter with a known source s (Detection::clutterSource), ClutterLabels::PerSource: label ~ row (s mod M) of
//     C, as a real detector labels a robot it sees: one class per object, wrong at rate p. Clutter without a source
//     stays uniform. Either way one label costs two engine outputs, so the landmarks' labels do not depend on the
//     choice.
// With M = 1 the header becomes semantic "none" and classifier "none" (one class is no information), and no
// detection carries a label. In both cases every landmark of the ground truth gets class (id mod M).
//
// Throws std::invalid_argument for M < 1, p outside [0, 1), p > 0 with M = 1, or a negative truth id other than
// kNotALandmark.

#include <cstdint>
#include <string>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// The class of landmark `id` among `classes`: id mod M.
int classOfLandmark(int id, int classes);

/// How clutter is labelled (above).
enum class ClutterLabels { Uniform, PerSource };

/// "uniform" | "per-source"; anything else throws std::invalid_argument.
ClutterLabels parseClutterLabels(const std::string& name);

/// Sets the header's classes, semantic kind and classifier, the ground truth's classes and every detection's label.
void assignClassLabels(MeasurementLog& log, int classes, double misclassification, std::uint32_t seed,
                       ClutterLabels clutterLabels = ClutterLabels::Uniform);

}  // namespace semslam
