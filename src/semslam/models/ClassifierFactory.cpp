#include "semslam/models/ClassifierFactory.h"

#include <stdexcept>
#include <string>

#include "semslam/models/AnalyticViewpointClassifier.h"
#include "semslam/models/TabulatedViewpointClassifier.h"

namespace semslam {

std::shared_ptr<const ViewpointClassifierModel> makeViewpointClassifier(const ClassifierModelSpec& spec,
                                                                        int classes,
                                                                        const std::filesystem::path& baseDirectory) {
  if (spec.kind != ClassifierModelSpec::Kind::ViewpointGaussian) {
    throw std::invalid_argument("makeViewpointClassifier: the classifier model is not ViewpointGaussian");
  }
  if (spec.table.empty()) {
    return std::make_shared<AnalyticViewpointClassifier>(spec.alpha, spec.sharpness, classes);
  }
  std::filesystem::path file(spec.table);
  if (file.is_relative() && !baseDirectory.empty()) file = baseDirectory / file;
  auto model = std::make_shared<TabulatedViewpointClassifier>(TabulatedViewpointClassifier::load(file));
  if (model->classes() != classes) {
    throw std::invalid_argument(file.string() + ": the viewpoint classifier table has " +
                                std::to_string(model->classes()) + " classes, the problem " +
                                std::to_string(classes));
  }
  return model;
}

CategoricalClassifierModel makeCategoricalClassifier(const ClassifierModelSpec& spec, int classes) {
  if (spec.kind != ClassifierModelSpec::Kind::Categorical) {
    throw std::invalid_argument("makeCategoricalClassifier: the classifier model is not Categorical");
  }
  return CategoricalClassifierModel(classes, spec.misclassification);
}

}  // namespace semslam
