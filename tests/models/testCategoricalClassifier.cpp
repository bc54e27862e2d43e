// The categorical (confusion-matrix) classifier model of paper B: the matrix from p and M, explicit matrices,
// likelihoods of labels and of probability vectors, normalisation over labels, sampling frequencies, validation.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "semslam/models/CategoricalClassifierModel.h"
#include "models/ModelsTesting.h"

namespace semslam {
namespace {

using test::matricesNear;

TEST(CategoricalClassifierModel, ConfusionMatrixFromMisclassificationRate) {
  const CategoricalClassifierModel model(4, 0.3);
  EXPECT_EQ(model.classes(), 4);
  for (int c = 0; c < 4; ++c) {
    for (int j = 0; j < 4; ++j) EXPECT_DOUBLE_EQ(model.likelihood(j, c), c == j ? 0.7 : 0.1);
  }
  const CategoricalClassifierModel perfect(2, 0.0);
  EXPECT_TRUE(matricesNear(perfect.confusion(), Matrix::Identity(2, 2), 0.0));
  EXPECT_EQ(perfect.logLikelihood(1, 0), -std::numeric_limits<double>::infinity());
}

TEST(CategoricalClassifierModel, LabelLikelihoodsSumToOneOverLabels) {
  Matrix explicitMatrix(3, 3);
  explicitMatrix << 0.8, 0.15, 0.05,  //
      0.1, 0.6, 0.3,                 //
      0.0, 0.25, 0.75;
  for (const CategoricalClassifierModel& model :
       {CategoricalClassifierModel(5, 0.37), CategoricalClassifierModel(2, 0.5), CategoricalClassifierModel(explicitMatrix)}) {
    for (int c = 0; c < model.classes(); ++c) {
      double sum = 0.0;
      for (int z = 0; z < model.classes(); ++z) sum += model.likelihood(z, c);
      EXPECT_NEAR(sum, 1.0, 1e-15);
    }
  }
  const CategoricalClassifierModel model(explicitMatrix);
  EXPECT_DOUBLE_EQ(model.likelihood(2, 1), 0.3);  // P(label 2 | class 1) = C[1, 2]
  EXPECT_TRUE(matricesNear(model.likelihoods(1), Vector3(0.15, 0.6, 0.25), 0.0));
  EXPECT_DOUBLE_EQ(model.logLikelihood(0, 0), std::log(0.8));
}

TEST(CategoricalClassifierModel, ProbabilityVectorLikelihoodIsTheSoftLabelMixture) {
  Matrix C(3, 3);
  C << 0.8, 0.15, 0.05, 0.1, 0.6, 0.3, 0.0, 0.25, 0.75;
  const CategoricalClassifierModel model(C);
  // One-hot vectors give the label likelihoods.
  for (int z = 0; z < 3; ++z) {
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(model.likelihood(Vector3(Vector3::Unit(z)), c), model.likelihood(z, c));
  }
  // P(z | c) = Σ_j z_j C[c, j].
  const Vector3 z(0.2, 0.5, 0.3);
  EXPECT_NEAR(model.likelihood(Vector(z), 0), 0.2 * 0.8 + 0.5 * 0.15 + 0.3 * 0.05, 1e-15);
  EXPECT_NEAR(model.likelihood(Vector(z), 2), 0.2 * 0.0 + 0.5 * 0.25 + 0.3 * 0.75, 1e-15);
  EXPECT_TRUE(matricesNear(model.likelihoods(Vector(z)), C * z, 1e-15));
  EXPECT_NEAR(model.logLikelihood(Vector(z), 1), std::log(0.2 * 0.1 + 0.5 * 0.6 + 0.3 * 0.3), 1e-15);
  // Printed with few digits: a sum within 1e-3 of one is accepted.
  EXPECT_NO_THROW(model.likelihood(Vector(Vector3(0.333, 0.333, 0.333)), 0));
}

TEST(CategoricalClassifierModel, SampledLabelsFollowTheConfusionRow) {
  const CategoricalClassifierModel model(4, 0.2);
  std::mt19937 rng(61);
  const int n = 200000;
  std::vector<int> counts(4, 0);
  for (int i = 0; i < n; ++i) ++counts[static_cast<std::size_t>(model.sampleLabel(2, rng))];
  for (int j = 0; j < 4; ++j) {
    const double p = model.likelihood(j, 2);
    EXPECT_NEAR(counts[static_cast<std::size_t>(j)] / double(n), p, 5.0 * std::sqrt(p * (1 - p) / n));
  }
  // A zero-probability label is never drawn; a seed repeats its draws.
  const CategoricalClassifierModel perfect(3, 0.0);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(perfect.sampleLabel(1, rng), 1);
  std::mt19937 first(3), second(3);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(model.sampleLabel(0, first), model.sampleLabel(0, second));
}

TEST(CategoricalClassifierModel, RejectsInvalidInputs) {
  EXPECT_THROW(CategoricalClassifierModel(1, 0.1), std::invalid_argument);
  EXPECT_THROW(CategoricalClassifierModel(3, 1.0), std::invalid_argument);
  EXPECT_THROW(CategoricalClassifierModel(3, -0.1), std::invalid_argument);
  EXPECT_THROW(CategoricalClassifierModel(3, std::nan("")), std::invalid_argument);
  EXPECT_THROW(CategoricalClassifierModel(Matrix::Identity(2, 3)), std::invalid_argument);
  EXPECT_THROW(CategoricalClassifierModel(Matrix::Identity(1, 1)), std::invalid_argument);
  EXPECT_THROW(CategoricalClassifierModel(Matrix::Constant(2, 2, 0.6)), std::invalid_argument);  // rows sum to 1.2
  Matrix negative(2, 2);
  negative << 1.2, -0.2, 0.5, 0.5;
  EXPECT_THROW(CategoricalClassifierModel{negative}, std::invalid_argument);
  const CategoricalClassifierModel model(3, 0.1);
  EXPECT_THROW(model.likelihood(3, 0), std::invalid_argument);
  EXPECT_THROW(model.likelihood(0, -1), std::invalid_argument);
  EXPECT_THROW(model.likelihood(Vector(Vector2(0.5, 0.5)), 0), std::invalid_argument);          // wrong length
  EXPECT_THROW(model.likelihood(Vector(Vector3(0.5, 0.6, 0.1)), 0), std::invalid_argument);     // sums to 1.2
  EXPECT_THROW(model.likelihood(Vector(Vector3(1.2, -0.1, -0.1)), 0), std::invalid_argument);   // negative
  EXPECT_THROW(model.likelihoods(Vector(Vector3(std::nan(""), 0.5, 0.5))), std::invalid_argument);
  std::mt19937 rng(1);
  EXPECT_THROW(model.sampleLabel(5, rng), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
