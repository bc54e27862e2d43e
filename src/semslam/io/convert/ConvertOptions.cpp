#include "semslam/io/convert/ConvertOptions.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "semslam/core/InputError.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam {

namespace {

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::size_t sigmaCount(int dimension) { return dimension == 3 ? 6u : 3u; }

}  // namespace

void validateConvertOptions(const ConvertOptions& options, int dimension) {
  if (options.classes < 1 || options.classes > kMaxLogClasses) {
    // Before any data is read: the labels' M x M confusion matrix is allocated from this count (10^5 classes died
    // with std::bad_alloc), and a log declares at most kMaxLogClasses.
    throw InputError("--classes must be in [1, " + std::to_string(kMaxLogClasses) + "], got " +
                     std::to_string(options.classes));
  }
  if (!std::isfinite(options.misclassification) || options.misclassification < 0.0 ||
      options.misclassification >= 1.0) {
    throw InputError("--misclassification must be in [0, 1), got " + number(options.misclassification));
  }
  if (options.classes == 1 && options.misclassification != 0.0) {
    throw InputError("--misclassification " + number(options.misclassification) +
                     " needs --classes 2 or more: with one class every label is right");
  }
  if (!std::isfinite(options.keyframePeriod) || options.keyframePeriod < 0.0) {
    throw InputError("--keyframe-period must be a finite number of seconds >= 0, got " +
                     number(options.keyframePeriod));
  }
  if (!std::isfinite(options.mapPriorSigma) || options.mapPriorSigma < 0.0) {
    throw InputError("--map-prior must be a finite standard deviation >= 0, got " + number(options.mapPriorSigma));
  }
  // A log's variances are in [1e-18, 1e18] (docs/measurement-log.md, "Limits").
  if (options.mapPriorSigma > 0.0 && (options.mapPriorSigma < 1e-9 || options.mapPriorSigma > 1e9)) {
    throw InputError("--map-prior must be 0 or in [1e-9, 1e9], got " + number(options.mapPriorSigma));
  }
  if (!options.initialPoseSigmas.empty()) {
    const std::size_t expected = sigmaCount(dimension);
    if (options.initialPoseSigmas.size() != expected) {
      throw InputError("--initial-pose-sigma needs " + std::to_string(expected) + " values for a " +
                       std::to_string(dimension) + "D dataset (" + (dimension == 3 ? "x,y,z,rx,ry,rz" : "x,y,theta") +
                       "), got " + std::to_string(options.initialPoseSigmas.size()));
    }
    for (double sigma : options.initialPoseSigmas) {
      if (!std::isfinite(sigma) || sigma < 1e-9 || sigma > 1e9) {
        throw InputError("--initial-pose-sigma values must be in [1e-9, 1e9], got " + number(sigma));
      }
    }
    // ... and its condition number at most 1e12 (io/InputMagnitudes.h).
    const auto [smallest, largest] =
        std::minmax_element(options.initialPoseSigmas.begin(), options.initialPoseSigmas.end());
    if (*largest > 1e6 * *smallest) {
      throw InputError("--initial-pose-sigma values must be within a factor 1e6 of each other, got " +
                       number(*smallest) + " and " + number(*largest));
    }
  }
}

std::string describeConvertOptions(const ConvertOptions& options, int dimension) {
  std::ostringstream out;
  out << "classes=" << options.classes << " misclassification=" << options.misclassification << " seed=" << options.seed
      << " keyframe-period=";
  if (options.keyframePeriod > 0.0) {
    out << options.keyframePeriod << " s";
  } else {
    out << "none";
  }
  out << " max-steps=";
  if (options.maxSteps > 0) {
    out << options.maxSteps;
  } else {
    out << "all";
  }
  out << " initial-pose-sigma=";
  const std::size_t n = sigmaCount(dimension);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) out << ',';
    out << (options.initialPoseSigmas.empty() ? kDefaultInitialPoseSigma : options.initialPoseSigmas[i]);
  }
  out << " map-prior=";
  if (options.mapPriorSigma > 0.0) {
    out << options.mapPriorSigma;
  } else {
    out << "none";
  }
  return out.str();
}

}  // namespace semslam
