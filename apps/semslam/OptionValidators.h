#pragma once
// Validators for numeric command-line values that CLI11 (2.1) would convert silently: an unsigned 64-bit value
// past 2^64 - 1 saturates (`--seed 99999999999999999999999` became 18446744073709551615) and "-5" wraps around.
// Each validator checks the text before CLI11 converts it; a refused value is a usage error (exit 2) whose
// message quotes at most a short, escaped excerpt of the value.

#include <CLI/CLI.hpp>

namespace semslam::cli {

/// Decimal digits only, at most 2^64 - 1: for every unsigned 64-bit option (the seeds).
const CLI::Validator& unsignedInteger64();

/// Decimal whole numbers (a transform): drops leading zeros, which CLI11 reads as octal ("--seed 0467" became 311,
/// "--steps 010" 8), and refuses a base prefix ("0x10", "0b1", "0o7") and, for an unsigned option, a minus sign
/// ("-5" wraps around). Other text passes unchanged, to CLI11's own conversion error.
const CLI::Validator& decimalInteger(bool isUnsigned);

/// Puts decimalInteger in front of the validators of every integer option (type INT or UINT) of `app` and of its
/// subcommands: main.cpp calls it once every command is added, so no integer option reads octal or hexadecimal.
void requireDecimalIntegers(CLI::App& app);

}  // namespace semslam::cli
