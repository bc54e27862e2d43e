#pragma once
// The three pose-graph readers behind readPoseGraph (PoseGraphFile.h), one per format, each in its own file.

#include <string>

#include "semslam/io/PoseGraphFile.h"

namespace semslam {

PoseGraphFile readG2oFile(const std::string& path);   // G2oReader.cpp
PoseGraphFile readToroFile(const std::string& path);  // ToroReader.cpp
PoseGraphFile readIsamFile(const std::string& path);  // IsamReader.cpp

}  // namespace semslam
