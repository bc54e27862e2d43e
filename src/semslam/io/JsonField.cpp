#include "semslam/io/JsonField.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/io/InputMagnitudes.h"

namespace semslam::jsonio {

namespace {

std::string joinKeys(std::initializer_list<std::string_view> a, std::initializer_list<std::string_view> b) {
  std::string joined;
  for (const auto* list : {&a, &b}) {
    for (std::string_view key : *list) {
      if (!joined.empty()) joined += ", ";
      joined += key;
    }
  }
  return joined;
}

bool contains(std::initializer_list<std::string_view> list, std::string_view key) {
  return std::find(list.begin(), list.end(), key) != list.end();
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/// True for the spellings of NaN and infinity that other writers put in strings.
bool looksNonFinite(const std::string& text) {
  const std::string t = lower(text);
  for (const char* word : {"nan", "+nan", "-nan", "inf", "+inf", "-inf", "infinity", "+infinity", "-infinity"}) {
    if (t == word) return true;
  }
  return false;
}

std::string shortened(std::string text, std::size_t limit = 40) {
  if (text.size() > limit) text = text.substr(0, limit) + "...";
  return text;
}

/// A bound as people write it: 1e7, 1e-18.
std::string magnitudeText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);  // "1e+07"
  std::string written = text;
  const auto e = written.find('e');
  if (e == std::string::npos) return written;
  std::string exponent = written.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return written.substr(0, e + 1) + (negative ? "-" : "") + exponent;
}

}  // namespace

std::string describeJson(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case Json::value_t::string:
      return "string " + shortened(value.dump());
    case Json::value_t::array:
      return "an array of " + std::to_string(value.size());
    case Json::value_t::object:
      return "an object";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "number " + value.dump();
    default:
      return "a value of an unsupported type";
  }
}

void JsonField::fail(const std::string& problem) const {
  throw InputError(location_->file, location_->line, path_.empty() ? problem : path_ + ": " + problem);
}

void JsonField::failType(std::string_view expected) const {
  std::string problem = "expected " + std::string(expected) + ", found " + describeJson(*value_);
  const bool numeric = expected.find("number") != std::string_view::npos ||
                       expected.find("integer") != std::string_view::npos;
  if (numeric && (value_->is_null() || (value_->is_string() && looksNonFinite(value_->get<std::string>())))) {
    problem += " (NaN and infinity are not allowed: every number must be finite)";
  }
  fail(problem);
}

void JsonField::requireObject(std::initializer_list<std::string_view> required,
                              std::initializer_list<std::string_view> optional) const {
  if (!value_->is_object()) failType("an object");
  for (const auto& item : value_->items()) {
    if (!contains(required, item.key()) && !contains(optional, item.key())) {
      fail("unknown field " + inputExcerpt(item.key()) + " (accepted: " + joinKeys(required, optional) + ")");
    }
  }
  for (std::string_view key : required) {
    if (!value_->contains(key)) fail("missing field '" + std::string(key) + "'");
  }
}

bool JsonField::has(std::string_view key) const { return value_->is_object() && value_->contains(key); }

JsonField JsonField::operator[](std::string_view key) const {
  if (!value_->is_object()) failType("an object");
  const auto found = value_->find(key);
  if (found == value_->end()) fail("missing field '" + std::string(key) + "'");
  return JsonField(*found, *location_, path_.empty() ? std::string(key) : path_ + "." + std::string(key));
}

std::size_t JsonField::arraySize() const {
  if (!value_->is_array()) failType("an array");
  return value_->size();
}

JsonField JsonField::at(std::size_t i) const {
  if (!value_->is_array()) failType("an array");
  return JsonField((*value_)[i], *location_, path_ + "[" + std::to_string(i) + "]");
}

double JsonField::number() const {
  if (!value_->is_number()) failType("a number");
  const double value = value_->get<double>();
  // Only an in-memory value can be non-finite here: the parser rejects numbers beyond the range of a double.
  if (!std::isfinite(value)) fail("not finite (NaN or infinity): every number must be finite");
  return value;
}

long long JsonField::integer(long long minimum, long long maximum) const {
  if (value_->is_number_float()) {
    fail("expected an integer, found " + describeJson(*value_) + " (write integers without a fraction or exponent)");
  }
  if (!value_->is_number_integer()) failType("an integer");
  const bool isUnsigned = value_->is_number_unsigned();
  const auto range = " in [" + std::to_string(minimum) + ", " + std::to_string(maximum) + "]";
  if (isUnsigned && value_->get<std::uint64_t>() > static_cast<std::uint64_t>(maximum)) {
    fail("integer " + value_->dump() + " is out of range: expected an integer" + range);
  }
  const long long value = value_->get<long long>();
  if (value < minimum || value > maximum) {
    fail("integer " + value_->dump() + " is out of range: expected an integer" + range);
  }
  return value;
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) failType("true or false");
  return value_->get<bool>();
}

std::string JsonField::string() const {
  if (!value_->is_string()) failType("a string");
  return value_->get<std::string>();
}

Vector JsonField::vector() const {
  const std::size_t n = arraySize();
  Vector v(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) v(static_cast<Eigen::Index>(i)) = at(i).number();
  return v;
}

Vector JsonField::vector(int length, std::string_view layout) const {
  if (!value_->is_array()) failType("an array of " + std::to_string(length) + " numbers " + std::string(layout));
  if (value_->size() != static_cast<std::size_t>(length)) {
    fail("expected " + std::to_string(length) + " numbers " + std::string(layout) + ", found " +
         std::to_string(value_->size()));
  }
  return vector();
}

Vector JsonField::coordinates(int length, std::string_view layout) const {
  const Vector v = vector(length, layout);
  for (Eigen::Index i = 0; i < v.size(); ++i) at(static_cast<std::size_t>(i)).coordinate();  // refuses, naming it
  return v;
}

double JsonField::coordinate() const {
  const double value = number();
  if (std::abs(value) > kMaxCoordinate) {
    fail(describeJson(*value_) + " is too large: coordinates, ranges and angles are at most " +
         magnitudeText(kMaxCoordinate) + " in magnitude (docs/measurement-log.md)");
  }
  return value;
}

Matrix JsonField::covariance(int n, std::string_view what) const {
  const std::string shape = std::to_string(n) + "x" + std::to_string(n);
  const std::string expected = "a " + shape + " matrix (" + std::to_string(n) + " rows over " + std::string(what) + ")";
  if (!value_->is_array()) failType(expected);
  if (value_->size() != static_cast<std::size_t>(n)) {
    fail("expected " + expected + ", found " + std::to_string(value_->size()) + " rows");
  }
  Matrix m(n, n);
  for (int i = 0; i < n; ++i) {
    const JsonField row = at(static_cast<std::size_t>(i));
    if (!row.value_->is_array()) row.failType("a row of " + std::to_string(n) + " numbers");
    if (row.value_->size() != static_cast<std::size_t>(n)) {
      row.fail("expected a row of " + std::to_string(n) + " numbers (the matrix is " + shape + "), found " +
               std::to_string(row.value_->size()));
    }
    for (int j = 0; j < n; ++j) m(i, j) = row.at(static_cast<std::size_t>(j)).number();
  }
  for (int i = 0; i < n; ++i) {
    // (A variance <= 0 is "not positive definite" below.)
    if (m(i, i) > 0.0 && !(m(i, i) >= kMinVariance && m(i, i) <= kMaxVariance)) {
      at(static_cast<std::size_t>(i)).at(static_cast<std::size_t>(i)).fail(
          "variance " + describeJson((*value_)[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)]) +
          " is outside [" + magnitudeText(kMinVariance) + ", " + magnitudeText(kMaxVariance) +
          "] (a standard deviation from 1e-9 to 1e9; docs/measurement-log.md)");
    }
  }
  const double scale = m.diagonal().cwiseAbs().maxCoeff();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (std::abs(m(i, j) - m(j, i)) > 1e-9 * scale) {
        char text[160];
        std::snprintf(text, sizeof text, "not symmetric: entry (%d, %d) is %.17g but (%d, %d) is %.17g", i, j,
                      m(i, j), j, i, m(j, i));
        fail(text);
      }
    }
  }
  // Averaging only the unequal pairs keeps an exactly symmetric input bit for bit (also where a sum would
  // overflow or a half would round).
  Matrix symmetric = m;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (m(i, j) != m(j, i)) symmetric(i, j) = symmetric(j, i) = 0.5 * m(i, j) + 0.5 * m(j, i);
    }
  }
  if (symmetric.llt().info() != Eigen::Success) {
    fail("not positive definite (a covariance must be; diagonal " + [&] {
      std::string d;
      for (int i = 0; i < n; ++i) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%.6g", i ? ", " : "", m(i, i));
        d += text;
      }
      return d;
    }() + ")");
  }
  // Positive definite here, and through every rotation and sum the models take of it (InputMagnitudes.h).
  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(symmetric, Eigen::EigenvaluesOnly);
  const double smallest = eigen.eigenvalues().minCoeff(), largest = eigen.eigenvalues().maxCoeff();
  if (!(smallest * kMaxConditionNumber >= largest)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "badly conditioned: eigenvalues from %.6g to %.6g, a ratio above %s (standard deviations along "
                  "its axes must be within a factor 1e6 of each other; docs/measurement-log.md)",
                  smallest, largest, magnitudeText(kMaxConditionNumber).c_str());
    fail(text);
  }
  return symmetric;
}

Json vectorToJson(const Vector& v) {
  Json array = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) array.push_back(v(i));
  return array;
}

Json matrixToJson(const Matrix& m) {
  Json rows = Json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    Json row = Json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace semslam::jsonio
