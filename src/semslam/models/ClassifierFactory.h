#pragma once
// ClassifierFactory: the classifier model that a measurement log's header (ClassifierModelSpec, MeasurementLog.h)
// describes, for readers, simulators and the pipeline.
//
//   ViewpointGaussian with `table` set   → TabulatedViewpointClassifier::load(table); a relative path is taken
//                                          relative to `baseDirectory` (the log file's folder);
//   ViewpointGaussian without a table    → AnalyticViewpointClassifier(alpha, sharpness, classes) (A, eq. 18);
//   Categorical                          → CategoricalClassifierModel(classes, misclassification) (paper B).
// Asking for a model of the other kind (or of kind None), or a table whose class count differs from `classes`,
// throws std::invalid_argument; the constructors' own checks apply (e.g. the analytic model needs 2 classes), and
// a bad table file throws semslam::InputError naming the file.

#include <filesystem>
#include <memory>

#include "semslam/models/CategoricalClassifierModel.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/models/ViewpointClassifierModel.h"

namespace semslam {

std::shared_ptr<const ViewpointClassifierModel> makeViewpointClassifier(
    const ClassifierModelSpec& spec, int classes, const std::filesystem::path& baseDirectory = {});

CategoricalClassifierModel makeCategoricalClassifier(const ClassifierModelSpec& spec, int classes);

}  // namespace semslam
