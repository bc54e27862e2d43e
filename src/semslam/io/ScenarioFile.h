#pragma once
// ScenarioFile: the aliased2d scenario as a JSON file (`semslam simulate aliased2d --scenario FILE`).
// The format, with a complete example, is specified in docs/simulators.md; data/scenarios/aliased2d_default.json
// is the built-in default written by writeAliased2dScenario.
//
//   {"format": "semslam-scenario", "version": 2, "kind": "aliased2d", "name": "...", "classes": 2,
//    "objects": [{"id": 0, "class": 0, "pose": [x, y, theta]}, ...],
//    "start": [x, y, theta],
//    "priors": {"initial_pose_covariance": [[..]], "object_covariance": [[..]], "pose_mean": "start"|"sampled",
//               "object_means": "sampled"|"truth"},
//    "motion": {"covariance": [[..]], "step_length": 1, "max_turn": 0.35,
//               "arena": {"center": [x, y], "radius": r}, "clearance": 1, "time_step": 1},
//    "sensor": {"body_to_sensor": [x, y, theta], "max_range": 6, "field_of_view": 1.57, "covariance": [[..]]},
//    "classifier": {"alpha": 0.25, "sharpness": 15}}
//
// Required: format, version, kind, objects, start, motion.arena (what depends on the layout). Every other field
// may be left out and then takes the built-in default's value (paper A's priors, noise and classifier); a
// missing name is the file's stem. Version 1 files (one "means": "sampled" | "truth" for both priors' means) are
// still read; the writer writes version 2.
//
// Reading validates everything and throws InputError(file, line, problem) at the first problem: invalid JSON
// (with the line where parsing stopped), a duplicate or unknown key (the message lists the accepted ones), a
// missing required field, a wrong type or length, a non-finite number, a covariance that is not symmetric
// positive definite, and every rule of validateAliased2dScenario (Aliased2dScenario.h). Problems found after
// parsing name the field's path ("sensor.max_range: must be >= 0 ...") with line 0 (the file as a whole).
//
// Writing builds the document with nlohmann-json and prints it with a 2-space indent (keys in the order above,
// numbers in the shortest form that reads back to the same double), atomically; reading what was written gives an
// equal scenario and writing that again the same bytes.

#include <string>

#include "semslam/sim/Aliased2dScenario.h"

namespace semslam {

inline constexpr const char* kScenarioFormat = "semslam-scenario";
inline constexpr int kScenarioVersion = 2;  // the version written; 1 is still read

/// Reads and validates an aliased2d scenario file. Throws InputError.
Aliased2dScenario readAliased2dScenario(const std::string& path);

/// Parses scenario text; `file` names it in messages and gives the default name. Throws InputError.
Aliased2dScenario parseAliased2dScenario(const std::string& text, const std::string& file);

/// The scenario as the JSON text writeAliased2dScenario writes (validated first: std::invalid_argument).
std::string aliased2dScenarioToJson(const Aliased2dScenario& scenario);

/// Writes the scenario atomically. Throws std::invalid_argument for an invalid scenario, std::runtime_error when
/// the file cannot be written.
void writeAliased2dScenario(const std::string& path, const Aliased2dScenario& scenario);

}  // namespace semslam
