// ClassBelief (paper B's P(c | l)), the semantic likelihoods of a detection, and the chi-square gate.

#include <gtest/gtest.h>

#include <cmath>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/ClassBelief.h"

using namespace semslam;

TEST(ClassBelief, StartsUniformAndFollowsBayesRule) {
  ClassBelief belief(3);
  EXPECT_NEAR(belief.probability(1), 1.0 / 3.0, 1e-15);
  const Vector likelihoods = Vector3(0.8, 0.1, 0.1);
  EXPECT_NEAR(belief.predictive(likelihoods), (0.8 + 0.1 + 0.1) / 3.0, 1e-15);
  belief.update(likelihoods);
  EXPECT_NEAR(belief.probability(0), 0.8, 1e-12);
  belief.update(likelihoods);
  EXPECT_NEAR(belief.probability(0), 0.64 / 0.66, 1e-12);
  EXPECT_EQ(belief.mostProbable(), 0);
}

TEST(ClassBelief, WeightTempersTheUpdateAndZeroLeavesItUnchanged) {
  ClassBelief belief(2);
  belief.update(Vector2(0.9, 0.1), 0.0);
  EXPECT_NEAR(belief.probability(0), 0.5, 1e-15);
  belief.update(Vector2(0.9, 0.1), 0.5);
  EXPECT_NEAR(belief.probability(0), 0.5 * 0.9 + 0.5 * 0.5, 1e-12);  // half Bayes, half prior
  // A label the belief rules out: no change unless the association is certain.
  ClassBelief certain(2);
  certain.update(Vector2(1.0, 0.0));
  certain.update(Vector2(0.0, 1.0), 1e-300);
  EXPECT_EQ(certain.probability(0), 1.0);
  EXPECT_EQ(certain.probabilities()(1), 0.0);  // exactly: a ruled-out class has no sliver of probability
  EXPECT_EQ(certain.predictive(Vector2(0.0, 1.0)), 0.0);
  EXPECT_THROW(certain.update(Vector2(0.0, 1.0), 1.0), std::invalid_argument);
  EXPECT_NEAR(belief.probabilities().sum(), 1.0, 1e-15);
}

TEST(ClassBelief, ThousandsOfConfidentLabelsNeitherUnderflowNorLock) {
  ClassBelief belief(2);
  for (int i = 0; i < 5000; ++i) belief.update(Vector2(0.99, 0.01));
  EXPECT_EQ(belief.mostProbable(), 0);
  EXPECT_TRUE(std::isfinite(belief.probabilities().sum()));
  for (int i = 0; i < 10000; ++i) belief.update(Vector2(0.01, 0.99));
  EXPECT_EQ(belief.mostProbable(), 1);  // the evidence turned, and the belief followed
}

TEST(ClassBelief, RejectsBadInput) {
  EXPECT_THROW(ClassBelief(0), std::invalid_argument);
  ClassBelief belief(2);
  EXPECT_THROW(belief.update(Vector3(1, 1, 1)), std::invalid_argument);
  EXPECT_THROW(belief.update(Vector2(0.5, 0.5), 1.5), std::invalid_argument);
  EXPECT_THROW(belief.update(Vector2(0.0, 0.0)), std::invalid_argument);  // impossible and certain
  EXPECT_THROW(belief.update(Vector2(std::nan(""), 0.5)), std::invalid_argument);
}

TEST(SemanticLikelihoods, AreTheConfusionColumnOfALabel) {
  LogHeader header;
  header.classes = 3;
  header.semantic = SemanticKind::Label;
  header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  header.classifier.misclassification = 0.2;
  Detection detection;
  detection.label = 2;
  const Vector likelihoods = semanticLikelihoods(header, detection);
  EXPECT_NEAR(likelihoods(2), 0.8, 1e-15);
  EXPECT_NEAR(likelihoods(0), 0.1, 1e-15);
  detection.label.reset();
  EXPECT_THROW(semanticLikelihoods(header, detection), std::invalid_argument);
  header.semantic = SemanticKind::None;
  EXPECT_TRUE(semanticLikelihoods(header, detection).isApprox(Vector::Ones(3)));
}

TEST(AssociationGate, ThresholdsAreChiSquareQuantiles) {
  const AssociationGate paper(AssociationGate::kPaperConfidence);
  EXPECT_NEAR(paper.threshold(2), -2.0 * std::log(0.1), 1e-9);  // χ²₂ quantile: −2 log(1 − p)
  const AssociationGate ours;
  EXPECT_NEAR(ours.threshold(2), -2.0 * std::log(1e-6), 1e-6);
  EXPECT_NEAR(AssociationGate(0.999).threshold(20), 45.3147, 1e-3);  // beyond the precomputed table
  LinearizedLikelihood likelihood;
  likelihood.dimension = 2;
  likelihood.innovationChi2 = 5.0;
  EXPECT_FALSE(paper.accepts(likelihood));
  EXPECT_TRUE(ours.accepts(likelihood));
  EXPECT_THROW(AssociationGate(1.0), std::invalid_argument);
  EXPECT_THROW(AssociationGate(0.0), std::invalid_argument);
}
