#pragma once
// Where each part of a converted log came from: the dataset file and line that a converter read it from, kept
// beside the log (the log's own types carry no provenance), so that a problem found in the log once it is made (a
// number beyond the reader's limits: docs/measurement-log.md, "Limits") is reported at the row that caused it, as
// the readers report their own errors (issue 16).
//
// A converter fills a LogSources parallel to the raw log it builds: one StepSources per step, one SourceLine per
// detection in the step's order, one per landmark truth entry in the header's order. finishConversion keeps it
// parallel through keyframing and truncation (a keyframe's composed odometry gets the range of rows composed).

#include <cstddef>
#include <string>
#include <vector>

namespace semslam {

/// A row of a dataset file: `line` is 1-based, 0 meaning the file as a whole. `firstLine`, when not 0, is the first
/// of several rows of the same file that made the value together, `line` the last (a keyframe's odometry composed
/// from the rows in between).
struct SourceLine {
  std::string file;
  std::size_t line = 0;
  std::size_t firstLine = 0;
};

/// The rows that made one time step.
struct StepSources {
  SourceLine step;        ///< the row that made the step (its time stamp)
  SourceLine odometry;    ///< the row whose values made the odometry increment into the step
  SourceLine truePose;    ///< the row of the step's true pose
  std::vector<SourceLine> detections;  ///< parallel to the step's detections
};

/// The rows that made a log: its header's sensor, its landmark truth (and the map prior made from it) and its steps.
struct LogSources {
  std::string dataset;                 ///< the folder or file converted: where a part without a row is reported
  SourceLine sensor;                   ///< where the sensor's numbers (body_to_sensor, max_range) come from
  std::vector<SourceLine> landmarks;   ///< parallel to header.landmarkTruth
  std::vector<StepSources> steps;      ///< parallel to the log's steps
};

}  // namespace semslam
