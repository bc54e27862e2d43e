#include "semslam/models/TabulatedViewpointClassifier.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/core/InputFile.h"
#include "semslam/core/JsonNesting.h"

namespace semslam {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr const char* kFormat = "semslam-viewpoint-classifier";
constexpr int kVersion = 1;

std::string entry(std::size_t c, const char* key) {
  return "classes[" + std::to_string(c) + "]." + key;
}
std::string entry(std::size_t c, const char* key, std::size_t i) {
  return entry(c, key) + "[" + std::to_string(i) + "]";
}

/// Validates tables in memory; problems are std::invalid_argument with the entry's path.
int validate(const std::vector<ViewpointTable>& tables) {
  if (tables.empty()) throw std::invalid_argument("classes: at least one class is needed");
  if (tables[0].mean.empty()) throw std::invalid_argument(entry(0, "mean") + ": no samples");
  const Eigen::Index d = tables[0].mean[0].size();
  if (d < 1) throw std::invalid_argument(entry(0, "mean", 0) + ": empty mean vector");
  for (std::size_t c = 0; c < tables.size(); ++c) {
    const ViewpointTable& t = tables[c];
    const std::size_t n = t.theta.size();
    if (n == 0) throw std::invalid_argument(entry(c, "theta") + ": no samples");
    if (t.mean.size() != n || t.covariance.size() != n) {
      throw std::invalid_argument("classes[" + std::to_string(c) + "]: theta, mean and covariance have " + std::to_string(n) + ", " +
                                  std::to_string(t.mean.size()) + " and " + std::to_string(t.covariance.size()) +
                                  " samples; they must have the same number");
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double th = t.theta[i];
      if (!std::isfinite(th) || th < -kPi || th >= kPi) {
        throw std::invalid_argument(entry(c, "theta", i) + ": " + std::to_string(th) +
                                    " is outside [-pi, pi) (pi and -pi are one viewpoint: list it once, as -pi)");
      }
      if (i > 0 && !(th > t.theta[i - 1])) {
        throw std::invalid_argument(entry(c, "theta", i) + ": the angles must be strictly increasing");
      }
      const Vector& m = t.mean[i];
      if (m.size() != d) {
        throw std::invalid_argument(entry(c, "mean", i) + ": " + std::to_string(m.size()) + " entries, expected " +
                                    std::to_string(d));
      }
      if (!m.allFinite()) throw std::invalid_argument(entry(c, "mean", i) + ": a NaN or infinite entry");
      const Matrix& S = t.covariance[i];
      if (S.rows() != d || S.cols() != d) {
        throw std::invalid_argument(entry(c, "covariance", i) + ": " + std::to_string(S.rows()) + "x" +
                                    std::to_string(S.cols()) + ", expected " + std::to_string(d) + "x" +
                                    std::to_string(d));
      }
      if (!S.allFinite()) throw std::invalid_argument(entry(c, "covariance", i) + ": a NaN or infinite entry");
      if ((S - S.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, S.cwiseAbs().maxCoeff())) {
        throw std::invalid_argument(entry(c, "covariance", i) + ": not symmetric");
      }
      Eigen::LLT<Matrix> llt(0.5 * (S + S.transpose()));
      if (llt.info() != Eigen::Success) {
        throw std::invalid_argument(entry(c, "covariance", i) + ": not positive definite");
      }
    }
  }
  return static_cast<int>(d);
}

using Json = nlohmann::json;

const Json& member(const Json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) throw std::invalid_argument(where + (where.empty() ? "" : ": ") + "missing \"" + key + "\"");
  return *it;
}

double number(const Json& value, const std::string& where) {
  if (!value.is_number()) throw std::invalid_argument(where + ": expected a number");
  return value.get<double>();
}

const Json& array(const Json& value, const std::string& where) {
  if (!value.is_array()) throw std::invalid_argument(where + ": expected an array");
  return value;
}

Vector vectorOf(const Json& value, const std::string& where) {
  array(value, where);
  Vector v(static_cast<Eigen::Index>(value.size()));
  for (std::size_t i = 0; i < value.size(); ++i) {
    v(static_cast<Eigen::Index>(i)) = number(value[i], where + "[" + std::to_string(i) + "]");
  }
  return v;
}

Matrix matrixOf(const Json& value, const std::string& where) {
  array(value, where);
  const auto rows = static_cast<Eigen::Index>(value.size());
  Matrix m(rows, rows);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const std::string rowWhere = where + "[" + std::to_string(r) + "]";
    const Vector row = vectorOf(value[static_cast<std::size_t>(r)], rowWhere);
    if (row.size() != rows) {
      throw std::invalid_argument(rowWhere + ": " + std::to_string(row.size()) + " entries in a row of a " +
                                  std::to_string(rows) + "-row matrix (it must be square)");
    }
    m.row(r) = row.transpose();
  }
  return m;
}

std::vector<ViewpointTable> parse(const Json& root) {
  if (!root.is_object()) throw std::invalid_argument("expected a JSON object at the top level");
  const Json& format = member(root, "format", "");
  if (!format.is_string() || format.get<std::string>() != kFormat) {
    throw std::invalid_argument(std::string("\"format\" must be \"") + kFormat + "\"");
  }
  const Json& version = member(root, "version", "");
  if (!version.is_number_integer() || version.get<long long>() != kVersion) {
    throw std::invalid_argument("unsupported \"version\" (this reader knows version " + std::to_string(kVersion) +
                                ")");
  }
  const Json& dimension = member(root, "dimension", "");
  if (!dimension.is_number_integer() || dimension.get<long long>() < 1) {
    throw std::invalid_argument("\"dimension\" must be an integer >= 1");
  }
  const auto d = static_cast<Eigen::Index>(dimension.get<long long>());
  const Json& classes = array(member(root, "classes", ""), "classes");
  std::vector<ViewpointTable> tables(classes.size());
  for (std::size_t c = 0; c < classes.size(); ++c) {
    const std::string where = "classes[" + std::to_string(c) + "]";
    if (!classes[c].is_object()) throw std::invalid_argument(where + ": expected an object");
    const Json& theta = array(member(classes[c], "theta", where), entry(c, "theta"));
    const Json& mean = array(member(classes[c], "mean", where), entry(c, "mean"));
    const Json& covariance = array(member(classes[c], "covariance", where), entry(c, "covariance"));
    ViewpointTable& t = tables[c];
    for (std::size_t i = 0; i < theta.size(); ++i) t.theta.push_back(number(theta[i], entry(c, "theta", i)));
    for (std::size_t i = 0; i < mean.size(); ++i) {
      t.mean.push_back(vectorOf(mean[i], entry(c, "mean", i)));
      if (t.mean.back().size() != d) {
        throw std::invalid_argument(entry(c, "mean", i) + ": " + std::to_string(t.mean.back().size()) +
                                    " entries, \"dimension\" is " + std::to_string(d));
      }
    }
    for (std::size_t i = 0; i < covariance.size(); ++i) {
      t.covariance.push_back(matrixOf(covariance[i], entry(c, "covariance", i)));
    }
  }
  return tables;
}

}  // namespace

TabulatedViewpointClassifier::TabulatedViewpointClassifier(std::vector<ViewpointTable> tables)
    : tables_(std::move(tables)) {
  try {
    dimension_ = validate(tables_);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string("TabulatedViewpointClassifier: ") + error.what());
  }
  for (ViewpointTable& t : tables_) {
    for (Matrix& S : t.covariance) S = 0.5 * (S + S.transpose());
  }
}

TabulatedViewpointClassifier TabulatedViewpointClassifier::fromJson(const std::string& text,
                                                                    const std::string& source) {
  Json root;
  try {
    requireJsonNestingAtMost(text, source, 1);
    root = Json::parse(text);
  } catch (const Json::exception& error) {
    // parse_error, and out_of_range for a number beyond a double (2e308; found by the fuzzer,
    // fuzz/findings/classifier/number_2e308_out_of_range).
    throw InputError(source, 0, "not valid JSON: " + boundedMessage(error.what(), 200));
  }
  std::vector<ViewpointTable> tables;
  try {
    tables = parse(root);
    validate(tables);
  } catch (const std::invalid_argument& error) {
    throw InputError(source, 0, std::string("viewpoint classifier table: ") + error.what());
  } catch (const Json::exception& error) {  // a value of the wrong JSON type that parse() did not check
    throw InputError(source, 0, "viewpoint classifier table: " + boundedMessage(error.what(), 200));
  }
  return TabulatedViewpointClassifier(std::move(tables));
}

TabulatedViewpointClassifier TabulatedViewpointClassifier::load(const std::filesystem::path& file) {
  return fromJson(readInputText(file.string()), file.string());
}

TabulatedViewpointClassifier TabulatedViewpointClassifier::tabulate(const ViewpointClassifierModel& model,
                                                                    int samples) {
  if (samples < 1) throw std::invalid_argument("tabulate: samples must be >= 1, got " + std::to_string(samples));
  std::vector<ViewpointTable> tables(static_cast<std::size_t>(model.classes()));
  for (int c = 0; c < model.classes(); ++c) {
    ViewpointTable& t = tables[static_cast<std::size_t>(c)];
    for (int i = 0; i < samples; ++i) {
      const double theta = -kPi + 2.0 * kPi * i / samples;
      t.theta.push_back(theta);
      t.mean.push_back(model.mean(c, theta));
      t.covariance.push_back(model.covariance(c, theta));
    }
  }
  return TabulatedViewpointClassifier(std::move(tables));
}

std::string TabulatedViewpointClassifier::toJson() const {
  Json classes = Json::array();
  for (const ViewpointTable& t : tables_) {
    Json means = Json::array(), covariances = Json::array();
    for (const Vector& m : t.mean) means.push_back(std::vector<double>(m.data(), m.data() + m.size()));
    for (const Matrix& S : t.covariance) {
      Json rows = Json::array();
      for (Eigen::Index r = 0; r < S.rows(); ++r) {
        const Vector row = S.row(r).transpose();
        rows.push_back(std::vector<double>(row.data(), row.data() + row.size()));
      }
      covariances.push_back(std::move(rows));
    }
    classes.push_back({{"theta", t.theta}, {"mean", std::move(means)}, {"covariance", std::move(covariances)}});
  }
  Json root = {{"format", kFormat}, {"version", kVersion}, {"dimension", dimension_}, {"classes", classes}};
  return root.dump() + "\n";
}

TabulatedViewpointClassifier::Segment TabulatedViewpointClassifier::locate(int classIndex, double theta) const {
  checkClass(classIndex);
  checkTheta(theta);
  const std::vector<double>& grid = tables_[static_cast<std::size_t>(classIndex)].theta;
  const int n = static_cast<int>(grid.size());
  double t = theta - 2.0 * kPi * std::floor((theta + kPi) / (2.0 * kPi));  // in [−π, π) up to rounding
  if (t >= kPi) t -= 2.0 * kPi;
  if (t < -kPi) t += 2.0 * kPi;
  // The last sample angle ≤ t, or −1 when t lies before the first.
  const int i = static_cast<int>(std::upper_bound(grid.begin(), grid.end(), t) - grid.begin()) - 1;
  Segment s;
  double left, right;
  if (i < 0) {
    s.left = n - 1;
    s.right = 0;
    left = grid[static_cast<std::size_t>(n - 1)] - 2.0 * kPi;
    right = grid[0];
  } else if (i == n - 1) {
    s.left = n - 1;
    s.right = 0;
    left = grid[static_cast<std::size_t>(n - 1)];
    right = grid[0] + 2.0 * kPi;
  } else {
    s.left = i;
    s.right = i + 1;
    left = grid[static_cast<std::size_t>(i)];
    right = grid[static_cast<std::size_t>(i + 1)];
  }
  s.width = right - left;
  s.lambda = std::clamp((t - left) / s.width, 0.0, 1.0);
  return s;
}

Vector TabulatedViewpointClassifier::mean(int classIndex, double theta, Vector* dMeanDTheta) const {
  const Segment s = locate(classIndex, theta);
  const ViewpointTable& t = tables_[static_cast<std::size_t>(classIndex)];
  const Vector& ml = t.mean[static_cast<std::size_t>(s.left)];
  const Vector& mr = t.mean[static_cast<std::size_t>(s.right)];
  if (dMeanDTheta) *dMeanDTheta = (mr - ml) / s.width;
  return (1.0 - s.lambda) * ml + s.lambda * mr;
}

Matrix TabulatedViewpointClassifier::covariance(int classIndex, double theta) const {
  const Segment s = locate(classIndex, theta);
  const ViewpointTable& t = tables_[static_cast<std::size_t>(classIndex)];
  return (1.0 - s.lambda) * t.covariance[static_cast<std::size_t>(s.left)] +
         s.lambda * t.covariance[static_cast<std::size_t>(s.right)];
}

}  // namespace semslam
