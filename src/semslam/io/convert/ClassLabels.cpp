#include "semslam/io/convert/ClassLabels.h"

#include <random>
#include <stdexcept>
#include <string>

#include "semslam/models/CategoricalClassifierModel.h"
#include "semslam/models/Sampling.h"

namespace semslam {

int classOfLandmark(int id, int classes) {
  if (classes < 1) throw std::invalid_argument("classOfLandmark: classes must be at least 1");
  if (id < 0) throw std::invalid_argument("classOfLandmark: landmark id " + std::to_string(id) + " is negative");
  return id % classes;
}

ClutterLabels parseClutterLabels(const std::string& name) {
  if (name == "uniform") return ClutterLabels::Uniform;
  if (name == "per-source") return ClutterLabels::PerSource;
  throw std::invalid_argument("unknown clutter labels \"" + name + "\" (uniform, per-source)");
}

void assignClassLabels(MeasurementLog& log, int classes, double misclassification, std::uint32_t seed,
                       ClutterLabels clutterLabels) {
  if (classes < 1) throw std::invalid_argument("assignClassLabels: classes must be at least 1");
  if (!(misclassification >= 0.0 && misclassification < 1.0)) {
    throw std::invalid_argument("assignClassLabels: the misclassification rate must be in [0, 1)");
  }
  if (classes == 1 && misclassification != 0.0) {
    throw std::invalid_argument("assignClassLabels: a misclassification rate needs two or more classes");
  }
  LogHeader& header = log.header;
  header.classes = classes;
  for (LandmarkTruth& truth : header.landmarkTruth) truth.classIndex = classOfLandmark(truth.id, classes);

  if (classes == 1) {
    header.semantic = SemanticKind::None;
    header.classifier = ClassifierModelSpec{};
    for (TimeStep& step : log.steps) {
      for (Detection& detection : step.detections) {
        detection.label.reset();
        detection.classVector.reset();
      }
    }
    return;
  }

  header.semantic = SemanticKind::Label;
  header.classifier = ClassifierModelSpec{};
  header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  header.classifier.misclassification = misclassification;
  const CategoricalClassifierModel model(classes, misclassification);
  std::mt19937 rng(seed);
  for (TimeStep& step : log.steps) {
    for (Detection& detection : step.detections) {
      detection.classVector.reset();
      if (detection.truthId && *detection.truthId >= 0) {
        detection.label = model.sampleLabel(classOfLandmark(*detection.truthId, classes), rng);
      } else if (clutterLabels == ClutterLabels::PerSource && detection.clutterSource) {
        detection.label = model.sampleLabel(*detection.clutterSource % classes, rng);
      } else if (!detection.truthId || *detection.truthId == kNotALandmark || *detection.truthId == kUnknownTruth) {
        const int label = static_cast<int>(uniform01(rng) * classes);
        detection.label = label < classes ? label : classes - 1;
      } else {
        throw std::invalid_argument("assignClassLabels: truth id " + std::to_string(*detection.truthId) +
                                    " is negative and not kNotALandmark");
      }
    }
  }
}

}  // namespace semslam
