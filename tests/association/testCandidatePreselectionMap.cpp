// CandidatePreselection (docs/association-front-end.md, §7) on a known but uncertain map of 800 landmarks over a
// 140 m square, with a real smoother: every landmark whose innovation passes the gate (geometric, and the joint
// gate's geometric part plus the semantic allowance) for some detection is selected — checked against the joint
// marginal over every landmark — and the selection is a small part of the map.

#include <gtest/gtest.h>

#include <random>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/CandidatePreselection.h"
#include "semslam/association/ClassBelief.h"
#include "semslam/association/MarginalLikelihood.h"
#include "semslam/association/PreselectionRadius.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/solve/SmootherFactory.h"

using namespace semslam;

TEST(PreselectionOnAPriorMap, SelectsEveryLandmarkThatCanPassAndFewOthers) {
  LogHeader header;
  header.classes = 3;
  header.semantic = SemanticKind::Label;
  header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  header.classifier.misclassification = 0.2;
  header.sensor.kind = SensorKind::RangeBearing;
  header.sensor.bodyToSensor = SE2(0.2, 0.0, 0.0);
  header.sensor.maxRange = 10.0;
  const MeasurementFactory factory(header);
  const AssociationGate gate;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n(0.0, 1.0);

  const std::unique_ptr<Smoother> smoother = smootherFactory(SmootherKind::Incremental)();
  FactorGraph factors;
  Values values;
  const Key pose = poseKey(0);
  const SE2 truePose(1.0, -2.0, 0.3);
  values.insert(pose, SE2(truePose.x() + 0.1, truePose.y() - 0.1, truePose.theta() + 0.01));
  const Matrix poseCovariance = Vector3(0.3 * 0.3, 0.3 * 0.3, 0.03 * 0.03).asDiagonal();
  factors.add(factory.posePriorFactor(pose, PosePrior{truePose, poseCovariance}));
  const int landmarks = 800;
  std::vector<Point2> truth;
  for (int j = 0; j < landmarks; ++j) {
    truth.emplace_back(70.0 * u(rng), 70.0 * u(rng));
    const double sigma = j % 7 == 0 ? 1.5 : 0.3;
    const Point2 mean = truth.back() + sigma * Point2(n(rng), n(rng));
    values.insert(landmarkKey(static_cast<std::uint64_t>(j)), mean);
    factors.add(factory.landmarkPriorFactor(landmarkKey(static_cast<std::uint64_t>(j)),
                                            LandmarkPrior{j, mean, Matrix::Identity(2, 2) * sigma * sigma}));
  }
  smoother->update(factors, values);

  // Detections of the landmarks within range of the true pose, plus clutter.
  const RangeBearingSensor2 sensor(std::get<SE2>(header.sensor.bodyToSensor));
  std::vector<Detection> detections;
  for (const Point2& l : truth) {
    const Vector2 z = sensor.predict(truePose, l);
    if (z(0) > 10.0) continue;
    Detection detection;
    detection.geometry = z + Vector2(0.05 * n(rng), 0.01 * n(rng));
    detection.covariance = Vector2(0.05 * 0.05, 0.01 * 0.01).asDiagonal();
    detection.label = static_cast<int>(detections.size() % 3);
    detections.push_back(detection);
  }
  for (int c = 0; c < 3; ++c) {
    Detection clutter;
    clutter.geometry = Vector2(2.0 + 8.0 * std::abs(u(rng)), 3.0 * u(rng));
    clutter.covariance = Vector2(0.05 * 0.05, 0.01 * 0.01).asDiagonal();
    clutter.label = c;
    detections.push_back(clutter);
  }
  ASSERT_GT(detections.size(), 5u);

  std::vector<Key> keys = {pose};
  for (int j = 0; j < landmarks; ++j) keys.push_back(landmarkKey(static_cast<std::uint64_t>(j)));
  const JointMarginal everyLandmark = smoother->jointMarginal(keys);
  for (bool jointGate : {false, true}) {
    CandidatePreselection preselection(header, gate);
    const auto keyOf = [](int j) { return landmarkKey(static_cast<std::uint64_t>(j)); };
    const auto active = [](int) { return true; };
    const std::vector<int> selected =
        preselection.select(*smoother, pose, detections, jointGate, landmarks, keyOf, active);
    EXPECT_TRUE(std::is_sorted(selected.begin(), selected.end()));
    EXPECT_LT(selected.size(), static_cast<std::size_t>(landmarks / 8)) << "joint gate " << jointGate;
    int passing = 0;
    for (const Detection& detection : detections) {
      const double allowance = jointGate ? semanticGateAllowance(semanticLikelihoods(header, detection)) : 0.0;
      for (int j = 0; j < landmarks; ++j) {
        const Key landmark = landmarkKey(static_cast<std::uint64_t>(j));
        const std::vector<FactorPtr> factor = {factory.detectionFactor(pose, landmark, detection)};
        const LinearizedLikelihood likelihood =
            linearizedLikelihood(factor, smoother->estimate(), everyLandmark.restrictedTo({pose, landmark}));
        if (likelihood.innovationChi2 > gate.threshold(2) + allowance) continue;
        ++passing;
        EXPECT_TRUE(std::binary_search(selected.begin(), selected.end(), j))
            << "landmark " << j << " passes the gate (chi2 " << likelihood.innovationChi2 << ") but was not selected";
      }
    }
    EXPECT_GE(passing, static_cast<int>(detections.size()) - 3);  // the true landmarks pass
  }
}
