// The viewpoint-dependent Gaussian classifier model (A, eq. 2, 18): the viewpoint angle and its Jacobians (2D and
// 3D), eq. 18's values and its swapped class, dh/dθ, the log-likelihood against a hand-computed Gaussian density,
// sampling, the tabulated model (reproduces the analytic one; viewpoint-dependent covariances; JSON round trip and
// file errors) and the factory from a log's classifier spec.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>

#include <unistd.h>

#include "semslam/core/InputError.h"
#include "semslam/models/AnalyticViewpointClassifier.h"
#include "semslam/models/ClassifierFactory.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/TabulatedViewpointClassifier.h"
#include "semslam/models/Viewpoint.h"
#include "models/ModelsTesting.h"

namespace semslam {
namespace {

constexpr double kPi = std::numbers::pi;
using test::matricesNear;

using test::randomSE3;
using test::uniform;

// ---- viewpoint ------------------------------------------------------------------------------------------------

TEST(Viewpoint, AngleIsTheCameraBearingInTheObjectFrame) {
  const SE2 object(1.0, 2.0, kPi / 2);  // object facing +y
  EXPECT_NEAR(viewpointAngle(SE2(1.0, 5.0, 0.3), object), 0.0, 1e-12);       // on the object's +x axis
  EXPECT_NEAR(viewpointAngle(SE2(-2.0, 2.0, -1.0), object), kPi / 2, 1e-12);  // on its +y axis (world −x)
  EXPECT_NEAR(viewpointAngle(SE2(1.0, -1.0, 2.0), object), kPi, 1e-12);       // behind it
  // The camera's heading does not matter.
  EXPECT_EQ(viewpointAngle(SE2(3.0, 4.0, 0.1), object), viewpointAngle(SE2(3.0, 4.0, -2.9), object));
  // Exactly behind: +π, never −π.
  EXPECT_EQ(viewpointAngle(SE2(-1.0, 0.0, 0.0), SE2()), kPi);
  EXPECT_THROW(viewpointAngle(SE2(1.0, 2.0, 0.0), object), std::domain_error);

  // 3D: the azimuth in the object's xy-plane; height is ignored.
  const SE3 object3(SO3::fromAxisAngle(Vector3::UnitZ(), kPi / 2), Point3(1.0, 2.0, 0.5));
  EXPECT_NEAR(viewpointAngle(SE3(SO3(), Point3(1.0, 5.0, 3.0)), object3), 0.0, 1e-12);
  EXPECT_NEAR(viewpointAngle(SE3(SO3(), Point3(-2.0, 2.0, -4.0)), object3), kPi / 2, 1e-12);
  EXPECT_THROW(viewpointAngle(SE3(SO3(), Point3(1.0, 2.0, 7.0)), object3), std::domain_error);
}

TEST(Viewpoint, JacobiansMatchCentralDifferences2D) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 60; ++trial) {
    const SE2 camera(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -3.1, 3.1));
    // Every fifth object is placed so that θ is near ±π, where the differences must wrap.
    SE2 object(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -3.1, 3.1));
    if (trial % 5 == 0) {
      const Point2 ahead = camera.translation() + object.rotation().rotate(Point2(2.0, 1e-7));
      object = SE2(SO2(object.theta()), ahead);
    }
    MatrixN<1, 3> Hcamera, Hobject;
    viewpointAngle(camera, object, &Hcamera, &Hobject);
    const std::function<double(const SE2&)> ofCamera = [&](const SE2& x) { return viewpointAngle(x, object); };
    const std::function<double(const SE2&)> ofObject = [&](const SE2& o) { return viewpointAngle(camera, o); };
    EXPECT_TRUE(matricesNear(Hcamera, test::numericalAngleDerivative(ofCamera, camera), 1e-8));
    EXPECT_TRUE(matricesNear(Hobject, test::numericalAngleDerivative(ofObject, object), 1e-8));
    EXPECT_EQ(Hcamera(0, 2), 0.0);
  }
}

TEST(Viewpoint, JacobiansMatchCentralDifferences3D) {
  std::mt19937 rng(32);
  for (int trial = 0; trial < 60; ++trial) {
    const SE3 camera = randomSE3(rng, 5.0);
    const SE3 object = randomSE3(rng, 5.0);
    MatrixN<1, 6> Hcamera, Hobject;
    viewpointAngle(camera, object, &Hcamera, &Hobject);
    const std::function<double(const SE3&)> ofCamera = [&](const SE3& x) { return viewpointAngle(x, object); };
    const std::function<double(const SE3&)> ofObject = [&](const SE3& o) { return viewpointAngle(camera, o); };
    EXPECT_TRUE(matricesNear(Hcamera, test::numericalAngleDerivative(ofCamera, camera), 1e-8));
    EXPECT_TRUE(matricesNear(Hobject, test::numericalAngleDerivative(ofObject, object), 1e-8));
  }
}

// ---- the analytic model of eq. 18 ----------------------------------------------------------------------------

TEST(AnalyticViewpointClassifier, Equation18Values) {
  const AnalyticViewpointClassifier model;  // α = 0.25, K = 15
  EXPECT_EQ(model.classes(), 2);
  EXPECT_EQ(model.dimension(), 2);
  // h_1(θ) = [α sin²(θ/2) + 1 − α, α − α sin²(θ/2)]: (0.75, 0.25), (0.875, 0.125), (1, 0).
  EXPECT_TRUE(matricesNear(model.mean(0, 0.0), Vector2(0.75, 0.25), 1e-15));
  EXPECT_TRUE(matricesNear(model.mean(0, kPi / 2), Vector2(0.875, 0.125), 1e-15));
  EXPECT_TRUE(matricesNear(model.mean(0, kPi), Vector2(1.0, 0.0), 1e-15));
  EXPECT_TRUE(matricesNear(model.mean(0, -kPi / 2), Vector2(0.875, 0.125), 1e-15));  // mirror symmetric
  EXPECT_TRUE(matricesNear(model.mean(0, 2 * kPi + 0.3), model.mean(0, 0.3), 1e-14));  // periodic
  // The second class is the first with its entries swapped.
  EXPECT_TRUE(matricesNear(model.mean(1, 0.0), Vector2(0.25, 0.75), 1e-15));
  EXPECT_TRUE(matricesNear(model.mean(1, kPi / 2), Vector2(0.125, 0.875), 1e-15));
  EXPECT_TRUE(matricesNear(model.mean(1, kPi), Vector2(0.0, 1.0), 1e-15));
  const AnalyticViewpointClassifier strong(0.6, 15.0);
  EXPECT_TRUE(matricesNear(strong.mean(0, kPi / 3), Vector2(0.6 * 0.25 + 0.4, 0.6 - 0.6 * 0.25), 1e-15));
  // Σ = (RᵀR)⁻¹ with R = K [[1, −0.5], [0, 1]] = [[1.25, 0.5], [0.5, 1]] / K², for both classes, at any θ.
  const Matrix expected = (Matrix(2, 2) << 1.25, 0.5, 0.5, 1.0).finished() / 225.0;
  for (int c = 0; c < 2; ++c) {
    EXPECT_TRUE(matricesNear(model.covariance(c, 0.7), expected, 1e-15));
    EXPECT_TRUE(matricesNear(model.noiseModel(c, -2.0)->information(), expected.inverse(), 1e-12));
  }
}

TEST(AnalyticViewpointClassifier, MeanDerivativeMatchesCentralDifferences) {
  const AnalyticViewpointClassifier model(0.4, 10.0);
  for (int c = 0; c < 2; ++c) {
    for (double theta = -3.1; theta < 3.2; theta += 0.37) {
      Vector derivative;
      model.mean(c, theta, &derivative);
      const double h = 1e-6;
      const Vector numerical = (model.mean(c, theta + h) - model.mean(c, theta - h)) / (2 * h);
      EXPECT_TRUE(matricesNear(derivative, numerical, 1e-9)) << "class " << c << " theta " << theta;
    }
  }
  Vector derivative;
  model.mean(0, kPi / 2, &derivative);
  EXPECT_TRUE(matricesNear(derivative, Vector2(0.2, -0.2), 1e-15));  // (α/2) sin θ (1, −1)
}

TEST(AnalyticViewpointClassifier, RejectsInvalidParameters) {
  EXPECT_THROW(AnalyticViewpointClassifier(0.25, 15.0, 3), std::invalid_argument);
  EXPECT_THROW(AnalyticViewpointClassifier(0.25, 15.0, 1), std::invalid_argument);
  EXPECT_THROW(AnalyticViewpointClassifier(-0.1), std::invalid_argument);
  EXPECT_THROW(AnalyticViewpointClassifier(1.5), std::invalid_argument);
  EXPECT_THROW(AnalyticViewpointClassifier(0.25, 0.0), std::invalid_argument);
  const AnalyticViewpointClassifier model;
  EXPECT_THROW(model.mean(2, 0.0), std::invalid_argument);
  EXPECT_THROW(model.mean(-1, 0.0), std::invalid_argument);
  EXPECT_THROW(model.mean(0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(model.logLikelihood(Vector3(0.5, 0.5, 0.0), 0, 0.0), std::invalid_argument);
}

/// log N(z; μ, Σ) for a 2-vector, written out by hand: −½ eᵀΣ⁻¹e − log 2π − ½ log det Σ.
double handGaussian2(const Vector2& z, const Vector2& mu, const Matrix2& S) {
  const double det = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
  const double e0 = z(0) - mu(0), e1 = z(1) - mu(1);
  const double quadratic = (S(1, 1) * e0 * e0 - 2.0 * S(0, 1) * e0 * e1 + S(0, 0) * e1 * e1) / det;
  return -0.5 * quadratic - std::log(2.0 * kPi) - 0.5 * std::log(det);
}

TEST(AnalyticViewpointClassifier, LogLikelihoodIsTheGaussianDensity) {
  const AnalyticViewpointClassifier model;
  const double theta = 0.3, alpha = 0.25, K = 15.0;
  const double s = std::sin(theta / 2) * std::sin(theta / 2);
  const Vector2 h0(alpha * s + 1 - alpha, alpha - alpha * s);
  const Vector2 z(0.7, 0.35);
  // With RᵀR = K² [[1, −½], [−½, 5/4]] and |Σ| = K⁻⁴: −½ K² (e₀² − e₀e₁ + 5/4 e₁²) − log 2π + 2 log K.
  const Vector2 e = z - h0;
  const double byHand = -0.5 * K * K * (e(0) * e(0) - e(0) * e(1) + 1.25 * e(1) * e(1)) - std::log(2 * kPi) +
                        2 * std::log(K);
  EXPECT_NEAR(model.logLikelihood(z, 0, theta), byHand, 1e-12);
  const Matrix2 S = (Matrix2() << 1.25, 0.5, 0.5, 1.0).finished() / (K * K);
  EXPECT_NEAR(model.logLikelihood(z, 0, theta), handGaussian2(z, h0, S), 1e-12);
  EXPECT_NEAR(model.logLikelihood(z, 1, theta), handGaussian2(z, Vector2(h0(1), h0(0)), S), 1e-12);
  // A measurement near class 0's mean is far more likely under class 0.
  EXPECT_GT(model.logLikelihood(h0, 0, theta), model.logLikelihood(h0, 1, theta) + 10.0);
}

TEST(AnalyticViewpointClassifier, SamplesHaveTheModelsMeanAndCovariance) {
  const AnalyticViewpointClassifier model;
  std::mt19937 rng(41);
  const int n = 100000;
  const Vector2 mean = model.mean(1, 1.0);
  const Matrix S = model.covariance(1, 1.0);
  Vector2 sum = Vector2::Zero();
  Matrix2 outer = Matrix2::Zero();
  for (int i = 0; i < n; ++i) {
    const Vector2 z = model.sample(1, 1.0, rng);
    sum += z;
    outer += (z - mean) * (z - mean).transpose();
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(sum(i) / n, mean(i), 5.0 * std::sqrt(S(i, i) / n));
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(outer(i, j) / n, S(i, j), 5.0 * std::sqrt((S(i, i) * S(j, j) + S(i, j) * S(i, j)) / n));
    }
  }
  std::mt19937 first(7), second(7);
  const Vector z1 = model.sample(0, 0.2, first);
  EXPECT_EQ(z1, model.sample(0, 0.2, second));  // a seed repeats its draws
  EXPECT_NE(z1, model.sample(0, 0.2, first));   // successive draws differ
}

// ---- tabulated ------------------------------------------------------------------------------------------------

/// A 3-class model whose mean and covariance both depend on θ, for exercising the tabulated model.
class VaryingModel final : public ViewpointClassifierModel {
 public:
  int classes() const override { return 3; }
  int dimension() const override { return 3; }
  Vector mean(int c, double theta, Vector* d = nullptr) const override {
    checkClass(c);
    Vector m(3);
    m << 0.2 + 0.1 * std::cos(theta + c), 0.3 + 0.1 * std::sin(2 * theta), 0.5 - 0.05 * c * std::cos(theta);
    if (d) {
      d->resize(3);
      *d << -0.1 * std::sin(theta + c), 0.2 * std::cos(2 * theta), 0.05 * c * std::sin(theta);
    }
    return m;
  }
  Matrix covariance(int c, double theta) const override {
    checkClass(c);
    Matrix S(3, 3);
    S << 0.02 * (1.5 + std::cos(theta)), 0.005 * std::sin(theta), 0.0,  //
        0.005 * std::sin(theta), 0.01 * (1.2 + std::sin(theta + c)), 0.002,  //
        0.0, 0.002, 0.03;
    return S;
  }
};

TEST(TabulatedViewpointClassifier, ReproducesTheAnalyticModel) {
  const AnalyticViewpointClassifier analytic;
  const TabulatedViewpointClassifier table = TabulatedViewpointClassifier::tabulate(analytic, 720);
  EXPECT_EQ(table.classes(), 2);
  EXPECT_EQ(table.dimension(), 2);
  std::mt19937 rng(51);
  // Linear interpolation error ≤ max|h''| Δ²/8 = (α/2)(2π/720)²/8 ≈ 1.2e-6.
  for (int trial = 0; trial < 500; ++trial) {
    const double theta = uniform(rng, -7.0, 7.0);  // also outside [−π, π): periodic
    for (int c = 0; c < 2; ++c) {
      Vector dTable, dAnalytic;
      EXPECT_TRUE(matricesNear(table.mean(c, theta, &dTable), analytic.mean(c, theta, &dAnalytic), 1.3e-6));
      EXPECT_TRUE(matricesNear(dTable, dAnalytic, 0.25 * 2 * kPi / 720));  // |h''| Δ
      EXPECT_TRUE(matricesNear(table.covariance(c, theta), analytic.covariance(c, theta), 1e-15));
      // |Δ log N| ≤ |Σ⁻¹ (z − h)|₁ · max|Δh| to first order.
      const Vector z = analytic.mean(1 - c, theta);
      const Vector gradient = analytic.noiseModel(c, theta)->information() * (z - analytic.mean(c, theta));
      EXPECT_NEAR(table.logLikelihood(z, c, theta), analytic.logLikelihood(z, c, theta),
                  1.3e-6 * gradient.lpNorm<1>() + 1e-9);
    }
  }
  // At the sample angles it is exact, including across the ±π seam.
  for (const double theta : {-kPi, -kPi + 2 * kPi / 720 * 17, kPi - 2 * kPi / 720}) {
    EXPECT_TRUE(matricesNear(table.mean(0, theta), analytic.mean(0, theta), 1e-15));
  }
  EXPECT_TRUE(matricesNear(table.mean(0, kPi), analytic.mean(0, kPi), 1e-15));
}

TEST(TabulatedViewpointClassifier, InterpolatesViewpointDependentCovariancesPeriodically) {
  const VaryingModel exact;
  // An irregular grid that does not start at −π: the wrap segment runs from the last sample to the first + 2π.
  std::vector<ViewpointTable> tables(3);
  for (int c = 0; c < 3; ++c) {
    for (double theta = -3.0; theta < 3.0; theta += 0.05 + 0.01 * (c + 1)) {
      tables[c].theta.push_back(theta);
      tables[c].mean.push_back(exact.mean(c, theta));
      tables[c].covariance.push_back(exact.covariance(c, theta));
    }
  }
  const TabulatedViewpointClassifier table(tables);
  std::mt19937 rng(52);
  for (int trial = 0; trial < 300; ++trial) {
    const double theta = uniform(rng, -kPi, kPi);
    for (int c = 0; c < 3; ++c) {
      // Gaps up to 2π − 6 + 0.08 ≈ 0.36 rad at the seam: error ≤ max|f''| gap²/8 ≈ 0.4 · 0.13/8.
      EXPECT_TRUE(matricesNear(table.mean(c, theta), exact.mean(c, theta), 7e-3));
      EXPECT_TRUE(matricesNear(table.covariance(c, theta), exact.covariance(c, theta), 4e-4));
    }
  }
  // Between two samples: exactly the linear blend, with the segment's slope as the derivative.
  const ViewpointTable& t = tables[1];
  const double mid = 0.25 * t.theta[10] + 0.75 * t.theta[11];
  Vector slope;
  EXPECT_TRUE(matricesNear(table.mean(1, mid, &slope), 0.25 * t.mean[10] + 0.75 * t.mean[11], 1e-14));
  EXPECT_TRUE(matricesNear(slope, (t.mean[11] - t.mean[10]) / (t.theta[11] - t.theta[10]), 1e-12));
  EXPECT_TRUE(matricesNear(table.covariance(1, mid), 0.25 * t.covariance[10] + 0.75 * t.covariance[11], 1e-15));
  // Across the seam: from the last sample to the first one, 2π later.
  const double last = t.theta.back(), first = t.theta.front() + 2 * kPi;
  const double across = 0.5 * (last + first);  // > π: wraps
  const Vector blended = 0.5 * (t.mean.back() + t.mean.front());
  EXPECT_TRUE(matricesNear(table.mean(1, across), blended, 1e-14));
  EXPECT_TRUE(matricesNear(table.mean(1, across - 2 * kPi), blended, 1e-14));
  // The default noise model (from the interpolated covariance) gives the hand-computed density.
  const Vector z = Vector3(0.25, 0.3, 0.45);
  const Matrix S = table.covariance(2, 0.4);
  const Vector e = z - table.mean(2, 0.4);
  const double byHand = -0.5 * e.dot(S.inverse() * e) - 1.5 * std::log(2 * kPi) - 0.5 * std::log(S.determinant());
  EXPECT_NEAR(table.logLikelihood(z, 2, 0.4), byHand, 1e-10);
}

TEST(TabulatedViewpointClassifier, OneSampleIsAConstantModel) {
  ViewpointTable t;
  t.theta = {0.5};
  t.mean = {Vector2(0.6, 0.4)};
  t.covariance = {Matrix(Vector2(0.01, 0.02).asDiagonal())};
  const TabulatedViewpointClassifier table({t, t});
  Vector slope;
  EXPECT_TRUE(matricesNear(table.mean(1, -2.0, &slope), Vector2(0.6, 0.4), 1e-15));
  EXPECT_TRUE(matricesNear(slope, Vector2::Zero(), 0.0));
}

TEST(TabulatedViewpointClassifier, JsonRoundTripIsExact) {
  const TabulatedViewpointClassifier table = TabulatedViewpointClassifier::tabulate(VaryingModel(), 37);
  const TabulatedViewpointClassifier again = TabulatedViewpointClassifier::fromJson(table.toJson(), "memory");
  ASSERT_EQ(again.classes(), 3);
  for (int c = 0; c < 3; ++c) {
    const ViewpointTable &a = table.tables()[c], &b = again.tables()[c];
    ASSERT_EQ(a.theta, b.theta);
    for (std::size_t i = 0; i < a.theta.size(); ++i) {
      EXPECT_EQ(a.mean[i], b.mean[i]);
      EXPECT_EQ(a.covariance[i], b.covariance[i]);
    }
  }
}

class TableFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("semslam-models-test-" + std::to_string(::getpid()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path write(const std::string& name, const std::string& text) {
    const std::filesystem::path file = directory_ / name;
    std::ofstream(file) << text;
    return file;
  }

  /// Loading `text` fails with an InputError whose message names the file and contains `fragment`.
  void expectError(const std::string& text, const std::string& fragment) {
    const std::filesystem::path file = write("bad.json", text);
    try {
      TabulatedViewpointClassifier::load(file);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(file.string()), std::string::npos) << message;
      EXPECT_NE(message.find(fragment), std::string::npos) << message << "\n(expected: " << fragment << ")";
    }
  }

  std::filesystem::path directory_;
};

const char* kGoodHeader = R"("format": "semslam-viewpoint-classifier", "version": 1, "dimension": 2)";

std::string tableText(const std::string& classes) {
  return std::string("{") + kGoodHeader + R"(, "classes": )" + classes + "}";
}

TEST_F(TableFiles, LoadsAFileAndTheFactoryResolvesItsPath) {
  const std::string text = tableText(R"([
    {"theta": [-3.14159, 0.0], "mean": [[0.7, 0.3], [0.8, 0.2]], "covariance": [[[0.01, 0.0], [0.0, 0.01]], [[0.02, 0.001], [0.001, 0.01]]]},
    {"theta": [0.0], "mean": [[0.3, 0.7]], "covariance": [[[0.01, 0.0], [0.0, 0.01]]]}])");
  const std::filesystem::path file = write("table.json", text);
  const TabulatedViewpointClassifier table = TabulatedViewpointClassifier::load(file);
  EXPECT_EQ(table.classes(), 2);
  EXPECT_TRUE(matricesNear(table.mean(0, 0.0), Vector2(0.8, 0.2), 0.0));
  EXPECT_TRUE(matricesNear(table.mean(1, 2.0), Vector2(0.3, 0.7), 0.0));

  ClassifierModelSpec spec;
  spec.kind = ClassifierModelSpec::Kind::ViewpointGaussian;
  spec.table = "table.json";
  const auto fromSpec = makeViewpointClassifier(spec, 2, directory_);
  EXPECT_TRUE(matricesNear(fromSpec->mean(0, 0.0), Vector2(0.8, 0.2), 0.0));
  EXPECT_THROW(makeViewpointClassifier(spec, 3, directory_), std::invalid_argument);  // class count differs
  spec.table = "missing.json";
  EXPECT_THROW(makeViewpointClassifier(spec, 2, directory_), InputError);
}

TEST_F(TableFiles, ReportsProblemsWithTheFileAndTheEntry) {
  const std::string cov = R"([[0.01, 0.0], [0.0, 0.01]])";
  expectError("{not json", "not valid JSON");
  expectError("[1, 2]", "top level");
  expectError(R"({"format": "other", "version": 1, "dimension": 2, "classes": []})", "\"format\"");
  expectError(R"({"format": "semslam-viewpoint-classifier", "version": 2, "dimension": 2, "classes": []})",
              "version");
  expectError(R"({"format": "semslam-viewpoint-classifier", "version": 1, "classes": []})", "missing \"dimension\"");
  expectError(tableText("[]"), "at least one class");
  expectError(tableText(R"([{"theta": [0.0], "mean": [[0.5, 0.5]]}])"), "classes[0]: missing \"covariance\"");
  expectError(tableText(R"([{"theta": [0.0, 1.0], "mean": [[0.5, 0.5]], "covariance": [)" + cov + "]}]"),
              "same number");
  expectError(tableText(R"([{"theta": [0.5, 0.2], "mean": [[0.5, 0.5], [0.5, 0.5]], "covariance": [)" + cov + "," +
                        cov + "]}]"),
              "classes[0].theta[1]: the angles must be strictly increasing");
  expectError(tableText(R"([{"theta": [3.141592653589793], "mean": [[0.5, 0.5]], "covariance": [)" + cov + "]}]"),
              "classes[0].theta[0]");
  expectError(tableText(R"([{"theta": [0.0], "mean": [[0.5, 0.5, 0.1]], "covariance": [)" + cov + "]}]"),
              "classes[0].mean[0]: 3 entries");
  expectError(tableText(R"([{"theta": [0.0], "mean": [[0.5, "x"]], "covariance": [)" + cov + "]}]"),
              "classes[0].mean[0][1]: expected a number");
  expectError(tableText(R"([{"theta": [0.0], "mean": [[0.5, 0.5]], "covariance": [)" + cov + R"(]},
                          {"theta": [0.0], "mean": [[0.5, 0.5]], "covariance": [[[1.0, 2.0], [2.0, 1.0]]]}])"),
              "classes[1].covariance[0]: not positive definite");
  expectError(tableText(R"([{"theta": [0.0], "mean": [[0.5, 0.5]], "covariance": [[[1.0, 0.2], [0.0, 1.0]]]}])"),
              "classes[0].covariance[0]: not symmetric");
  expectError(tableText(R"([{"theta": [0.0], "mean": [[0.5, 0.5]], "covariance": [[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]]}])"),
              "classes[0].covariance[0]: 3x3, expected 2x2");
  try {
    TabulatedViewpointClassifier::load(directory_ / "absent.json");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("absent.json"), std::string::npos);
  }
  // The in-memory constructor checks the same, with std::invalid_argument.
  ViewpointTable bad;
  bad.theta = {0.0};
  bad.mean = {Vector2(0.5, 0.5)};
  bad.covariance = {Matrix::Zero(2, 2)};
  EXPECT_THROW(TabulatedViewpointClassifier({bad}), std::invalid_argument);
}

TEST(ClassifierFactory, BuildsTheModelTheSpecNames) {
  ClassifierModelSpec spec;
  spec.kind = ClassifierModelSpec::Kind::ViewpointGaussian;
  spec.alpha = 0.5;
  spec.sharpness = 10.0;
  const auto analytic = makeViewpointClassifier(spec, 2);
  EXPECT_TRUE(matricesNear(analytic->mean(0, 0.0), Vector2(0.5, 0.5), 1e-15));
  EXPECT_TRUE(matricesNear(analytic->covariance(0, 0.0), AnalyticViewpointClassifier(0.5, 10.0).covariance(0, 0.0),
                           0.0));
  EXPECT_THROW(makeViewpointClassifier(spec, 3), std::invalid_argument);
  EXPECT_THROW(makeCategoricalClassifier(spec, 2), std::invalid_argument);
  spec.kind = ClassifierModelSpec::Kind::Categorical;
  spec.misclassification = 0.2;
  const CategoricalClassifierModel categorical = makeCategoricalClassifier(spec, 3);
  EXPECT_DOUBLE_EQ(categorical.likelihood(1, 1), 0.8);
  EXPECT_DOUBLE_EQ(categorical.likelihood(2, 1), 0.1);
  EXPECT_THROW(makeViewpointClassifier(spec, 2), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
