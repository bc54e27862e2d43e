#pragma once
// Validators for numeric command-line values that CLI11 (2.1) would convert silently: an unsigned 64-bit value
// past 2^64 - 1 saturates (`--seed 99999999999999999999999` became 18446744073709551615) and "-5" wraps around.
// Each validator checks the text before CLI11 converts it; a refused value is a usage error (exit 2) whose
// message quotes at most a short, escaped excerpt of the value.

#include <CLI/CLI.hpp>

namespace semslam::cli {

/// Decimal digits only, at most 2^64 - 1: for every unsigned 64-bit option (the seeds).
const CLI::Validator& unsignedInteger64();

}  // namespace semslam::cli
