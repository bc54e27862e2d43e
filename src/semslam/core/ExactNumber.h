#pragma once
// Text for a double that reads back (strtod, std::from_chars) to exactly the same double, in the two forms the
// files of semslam use:
//   shortestExactNumber    the shortest such text (std::to_chars): 0.1 → "0.1", 1e300 → "1e+300", −0 → "-0";
//   seventeenDigitNumber   printf's "%.17g": always 17 significant digits, so 0.1 → "0.10000000000000001".
// Both are exact round trips for every finite double; they differ in bytes, so each file format keeps the one it
// has always written.

#include <string>

namespace semslam {

std::string shortestExactNumber(double value);
std::string seventeenDigitNumber(double value);

}  // namespace semslam
