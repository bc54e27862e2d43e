#include "semslam/association/UnassignedHypothesis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace semslam {
namespace {

constexpr double kMinimumRange = 1e-3;  // m: a detection at the sensor has no bearing

void requirePositiveRate(double rate) {
  if (!(rate > 0.0) || !std::isfinite(rate)) throw std::invalid_argument("unassigned rate must be positive and finite");
}

}  // namespace

UnassignedHypothesis::UnassignedHypothesis(const LogHeader& header, double rate, std::optional<double> rateWeight,
                                           std::optional<double> rateMemory)
    : kind_(header.sensor.kind),
      dimension_(header.dimension),
      rate_(rate),
      rateWeight_(rateWeight),
      specRange_(header.sensor.maxRange),
      specFieldOfView_(header.sensor.fieldOfView) {
  requirePositiveRate(rate);
  if (rateWeight && (!(*rateWeight > 0.0) || !std::isfinite(*rateWeight))) {
    throw std::invalid_argument("the unassigned rate's prior weight must be positive and finite (steps)");
  }
  if (rateMemory) {
    if (!(*rateMemory >= 1.0) || !std::isfinite(*rateMemory)) {
      throw std::invalid_argument("the unassigned rate's memory must be finite and at least 1 (steps)");
    }
    if (!rateWeight) {
      throw std::invalid_argument("the unassigned rate's memory needs an estimated rate (a prior weight)");
    }
    countDiscount_ = 1.0 - 1.0 / *rateMemory;
  }
}

double UnassignedHypothesis::rate() const {
  if (!rateWeight_) return rate_;
  return (*rateWeight_ * rate_ + unassignedCounted_) / (*rateWeight_ + stepsCounted_);  // the Gamma posterior mean
}

void UnassignedHypothesis::countStep(int unassignedDetections) {
  if (unassignedDetections < 0) throw std::invalid_argument("countStep: a negative count of unassigned detections");
  if (!rateWeight_) return;
  unassignedCounted_ = countDiscount_ * unassignedCounted_ + unassignedDetections;  // γ n + n_k (γ = 1: n + n_k)
  stepsCounted_ = countDiscount_ * stepsCounted_ + 1.0;
}

UnassignedHypothesis UnassignedHypothesis::withRate(double rate) const {
  requirePositiveRate(rate);
  UnassignedHypothesis fixed = *this;
  fixed.rate_ = rate;
  fixed.rateWeight_.reset();
  fixed.unassignedCounted_ = 0.0;
  fixed.stepsCounted_ = 0.0;
  return fixed;
}

UnassignedHypothesis::Polar UnassignedHypothesis::polarOf(const Detection& detection) const {
  const Vector& g = detection.geometry;
  Polar p;
  switch (kind_) {
    case SensorKind::RangeBearing:
      p.range = g(0);
      p.bearing = g(1);
      break;
    case SensorKind::RangeBearingElevation:
      p.range = g(0);
      p.bearing = g(1);
      p.elevation = g(2);
      break;
    case SensorKind::RelativePosition:
    case SensorKind::RelativePose: return polarOfPosition(g.head(dimension_));  // the position part: x, y[, z]
  }
  p.range = std::max(std::abs(p.range), kMinimumRange);
  return p;
}

UnassignedHypothesis::Polar UnassignedHypothesis::polarOfPosition(const Vector& position) const {
  Polar p;
  p.range = std::max(position.norm(), kMinimumRange);
  p.bearing = std::atan2(position(1), position(0));
  if (position.size() == 3) p.elevation = std::atan2(position(2), position.head(2).norm());
  return p;
}

void UnassignedHypothesis::observe(const Detection& detection) {
  const Polar p = polarOf(detection);
  observedRange_ = std::max(observedRange_, p.range);
  observedBearing_ = std::max(observedBearing_, std::abs(p.bearing));
  observedElevation_ = std::max(observedElevation_, std::abs(p.elevation));
  observedAny_ = true;
}

double UnassignedHypothesis::maxRange() const { return specRange_ > 0.0 ? specRange_ : observedRange_; }

double UnassignedHypothesis::bearingSpan() const {
  if (specFieldOfView_ > 0.0) return std::min(specFieldOfView_, 2.0 * std::numbers::pi);
  return std::min(2.0 * observedBearing_, 2.0 * std::numbers::pi);
}

double UnassignedHypothesis::elevationSpan() const { return std::min(2.0 * observedElevation_, std::numbers::pi); }

void UnassignedHypothesis::requireField() const {
  if (!observedAny_ && !(dimension_ == 2 && specRange_ > 0.0 && specFieldOfView_ > 0.0)) {
    throw std::logic_error("unassigned hypothesis: the sensor field is unknown before the first detection");
  }
}

double UnassignedHypothesis::logCartesianDensity() const {
  requireField();
  // Spans of zero (every detection dead ahead so far) are widened to a minimal opening so V > 0.
  const double rMax = std::max(maxRange(), kMinimumRange);
  const double phi = std::max(bearingSpan(), 1e-3);
  double logVolume = 0.0;
  if (dimension_ == 2) {
    logVolume = std::log(phi) + 2.0 * std::log(rMax) - std::log(2.0);
  } else {
    const double psi = std::max(elevationSpan(), 1e-3);
    logVolume = 3.0 * std::log(rMax) - std::log(3.0) + std::log(phi) + std::log(2.0 * std::sin(psi / 2.0));
  }
  return std::log(rate()) - logVolume;
}

bool UnassignedHypothesis::inField(const Vector& position) const {
  requireField();
  const Polar p = polarOfPosition(position);
  const bool inElevation = dimension_ == 2 || std::abs(p.elevation) <= elevationSpan() / 2.0;
  return p.range <= maxRange() && std::abs(p.bearing) <= bearingSpan() / 2.0 && inElevation;
}

double UnassignedHypothesis::logDensity(const Detection& detection) const {
  return logLandmarkDensity() + logBackProjectionJacobian(detection);
}

double UnassignedHypothesis::logBackProjectionJacobian(const Detection& detection) const {
  const Polar p = polarOf(detection);
  switch (kind_) {
    case SensorKind::RangeBearing: return std::log(p.range);
    case SensorKind::RangeBearingElevation:
      return 2.0 * std::log(p.range) + std::log(std::max(std::cos(p.elevation), 1e-12));
    case SensorKind::RelativePosition: return 0.0;
    case SensorKind::RelativePose: return 0.0;  // a pose measures the landmark's variable itself: J = 1
  }
  return 0.0;
}

double UnassignedHypothesis::logLandmarkDensity() const {
  if (kind_ != SensorKind::RelativePose) return logCartesianDensity();
  // A uniform orientation: 1 / 2π in 2D, 1 / 8π² over SO(3) (its Haar measure) in 3D.
  const double logOrientation = dimension_ == 2 ? -std::log(2.0 * std::numbers::pi)
                                                : -std::log(8.0 * std::numbers::pi * std::numbers::pi);
  return logCartesianDensity() + logOrientation;
}

double switchDistanceSquared(double logDensity, int measurementDimension, double logDeterminantS,
                             double logLabelPredictiveRatio) {
  return -2.0 * (logDensity + 0.5 * measurementDimension * std::log(2.0 * std::numbers::pi) + 0.5 * logDeterminantS -
                 logLabelPredictiveRatio);
}

}  // namespace semslam
