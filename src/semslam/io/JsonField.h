#pragma once
// JsonField: one value of a JSON record read from a line of a file, with every access checked.
//
// Internal to the io layer (it includes nlohmann/json, which is not part of semslam's installed interface):
// the JSON-lines readers use it to turn a parsed line into typed values. A field knows where it is (the file, the
// 1-based line, and its path inside the record, "detections[2].covariance"), and every accessor checks what it
// returns and throws InputError(file, line, "<path>: <problem>") naming what is wrong: a missing or unknown key,
// a wrong type (with the value found), a non-finite number, a wrong length, a matrix that is not square,
// symmetric or positive definite.
//
// JSON has no literal for NaN or infinity. A writer that meets one writes `null` (nlohmann::json) or a string
// ("NaN", "Infinity": Python's json module writes the bare words, which are not JSON and fail to parse); all of
// these are rejected as "expected a number", with a hint that non-finite values are not allowed.

#include <cstddef>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "semslam/geometry/Matrix.h"

namespace semslam::jsonio {

using Json = nlohmann::ordered_json;

/// Where a record is: the file and the 1-based line.
struct JsonLocation {
  std::string file;
  std::size_t line = 0;
};

class JsonField {
 public:
  /// The whole record (path "").
  JsonField(const Json& value, const JsonLocation& location) : value_(&value), location_(&location) {}

  const Json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  const JsonLocation& location() const { return *location_; }

  /// Throws InputError(file, line, "<path>: <problem>") ("<problem>" at the top of the record).
  [[noreturn]] void fail(const std::string& problem) const;

  // ---- objects ----

  /// Requires an object whose keys are all in `required` or `optional`, with every key of `required` present.
  /// The message for an unknown key lists the accepted ones (a typo must not pass silently).
  void requireObject(std::initializer_list<std::string_view> required,
                     std::initializer_list<std::string_view> optional = {}) const;
  bool has(std::string_view key) const;
  /// The member `key`, which must exist ("missing field 'key'" otherwise).
  JsonField operator[](std::string_view key) const;

  // ---- arrays ----

  /// Requires an array and returns its size.
  std::size_t arraySize() const;
  /// Element i of an array.
  JsonField at(std::size_t i) const;

  // ---- scalars ----

  /// A finite number (an integer or a floating-point literal).
  double number() const;
  /// An integer literal (no fraction or exponent: 2, not 2.0) in [minimum, maximum].
  long long integer(long long minimum, long long maximum) const;
  bool boolean() const;
  std::string string() const;

  // ---- vectors and matrices ----

  /// An array of finite numbers; any length.
  Vector vector() const;
  /// An array of exactly `length` finite numbers; `layout` describes them in the message ("[x, y, theta]").
  Vector vector(int length, std::string_view layout) const;
  /// vector(length, layout) whose every entry is at most kMaxCoordinate in magnitude (io/InputMagnitudes.h):
  /// positions, translations, angles, ranges.
  Vector coordinates(int length, std::string_view layout) const;
  /// number(), at most kMaxCoordinate in magnitude.
  double coordinate() const;
  /// An n×n covariance: an array of n arrays of n finite numbers, symmetric to
  /// |Σij − Σji| ≤ 1e-9·max_k |Σkk|, every positive variance Σii in [kMinVariance, kMaxVariance] (io/InputMagnitudes.h),
  /// positive definite (a Cholesky factorisation exists). Returned exactly
  /// symmetric ((Σ + Σᵀ)/2, which leaves an exactly symmetric input unchanged). `what` describes its rows in
  /// messages ("x, y, theta").
  Matrix covariance(int n, std::string_view what) const;

 private:
  JsonField(const Json& value, const JsonLocation& location, std::string path)
      : value_(&value), location_(&location), path_(std::move(path)) {}
  [[noreturn]] void failType(std::string_view expected) const;

  const Json* value_;
  const JsonLocation* location_;
  std::string path_;
};

/// A short description of a JSON value for messages: `string "NaN"`, `null`, `array of 3`, `number 2.5`.
std::string describeJson(const Json& value);

/// The numbers of a vector or matrix as JSON (round-trip exact when dumped).
Json vectorToJson(const Vector& v);
Json matrixToJson(const Matrix& m);

}  // namespace semslam::jsonio
