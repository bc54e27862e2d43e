#pragma once
// Pose-graph files: g2o, TORO and iSAM, read into a factor graph with an initial estimate, and g2o written back.
//
// Formats (one record per line; fields separated by blanks; a line whose first non-blank character is '#' is a
// comment; blank lines are skipped). Full description: docs/file-formats.md.
//   g2o   VERTEX_SE2 id x y θ | VERTEX_XY id x y | VERTEX_SE3:QUAT id x y z qx qy qz qw |
//         EDGE_SE2 i j dx dy dθ I11 I12 I13 I22 I23 I33 | EDGE_SE2_XY i l dx dy I11 I12 I22 |
//         EDGE_SE3:QUAT i j x y z qx qy qz qw + 21 upper-triangular information entries, row-major | FIX id...
//         The EDGE_SE3:QUAT information, over g2o's (x y z qx qy qz), is taken as the information of our
//         translation-first SE3 log error, as GTSAM reads it. Quaternions are normalised (a zero one is an error).
//         A vertex must be declared on an earlier line than the edges and FIX lines that name it; one file is
//         either 2D or 3D. A vertex fixed twice is listed once in `fixed`.
//   TORO  VERTEX2 id x y θ | EDGE2 i j dx dy dθ I_xx I_xy I_yy I_θθ I_xθ I_yθ | EQUIV i j
//         (information Ω = [I_xx I_xy I_xθ; I_xy I_yy I_yθ; I_xθ I_yθ I_θθ]); VERTEX and EDGE, as TORO writes
//         them, are synonyms of VERTEX2 and EDGE2. EQUIV asks TORO to collapse the edge between i and j,
//         treating it as exact; it adds no factor here (nor in TORO's plain load or GTSAM's load2D) and is
//         returned in `equivalences` for a caller who wants to act on it.
//   iSAM  EDGE2/ODOMETRY i j dx dy dθ + 6 upper-triangular square-root information entries (row-major) |
//         LANDMARK i l dx dy + 3 square-root information entries (landmark position in the frame of pose i).
//         No vertex lines: the first pose of the first odometry record is the identity; a pose first named by an
//         odometry record is chained from the record's other, known pose (x_j = x_i·z, or x_i = x_j·z⁻¹); a
//         landmark is placed by its first observation, x_i ⊕ z. A LANDMARK must name a pose that has appeared.
// EDGE2 means different things in TORO and iSAM, so the format is always given, never guessed.
//
// Keys: g2o and TORO ids are plain keys (one id space: Key == id); iSAM poses are x<i> and landmarks l<i>.
// Between edges become BetweenFactor<SE2|SE3>, point edges RelativePointFactor<SE2, Point2>; factors are in file
// order. Units are the file's own (metres and radians in all the shared datasets); nothing is rescaled.
// Every problem throws InputError naming the file, the line (0 for the file as a whole) and the problem: a file
// that does not exist, no records, no pose; an unknown record type (a known but unsupported one says so); too
// few or too many fields (with the expected field list); a non-numeric, non-finite or out-of-range number; an id
// that is not a non-negative integer; a duplicate vertex; an edge naming a vertex that is not declared yet or
// has the wrong type, or joining a vertex to itself; 2D and 3D records in one file; an information or
// square-root information matrix that is not positive definite; a zero quaternion.

#include <string>
#include <utility>
#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"

namespace semslam {

enum class GraphFormat { G2o, Toro, Isam };

/// "g2o", "toro", "isam" -> GraphFormat; throws InputError otherwise.
GraphFormat parseGraphFormat(const std::string& name);

struct PoseGraphFile {
  FactorGraph factors;                            // the file's own edges, in file order
  Values initial;                                 // the file's vertices, or the chained initialisation (iSAM)
  std::vector<Key> fixed;                         // vertices named by FIX lines, in file order
  std::vector<std::pair<Key, Key>> equivalences;  // TORO EQUIV i j records, in file order (no factors)
  Key firstPose = 0;  // the first pose vertex of the file (iSAM: the first pose of the first edge)
  int dimension = 2;  // 2 or 3
};

PoseGraphFile readPoseGraph(const std::string& path, GraphFormat format);

/// Writes `values` as vertices (SE2 → VERTEX_SE2, Point2 → VERTEX_XY, SE3 → VERTEX_SE3:QUAT, by g2o id), then
/// FIX lines for `fixed`, then every BetweenFactor<SE2|SE3> and RelativePointFactor<SE2, Point2> of `graph` in
/// graph order as g2o edges (information = RᵀR of its noise model; a robust kernel is not written). Other
/// factors (priors, ...) are not g2o records and are skipped. Numbers are written in the shortest form that reads
/// back to the same double.
/// g2o has one numeric id space, so keys are numbered (G2oIds.h): a plain key k keeps id k, a pose key x<i> gets
/// id i, and every other typed key (l<i>, ...) is numbered after the largest of those ids, in key order. A graph
/// read from g2o or TORO is therefore written with its own ids; an iSAM graph keeps its pose numbers and its
/// landmarks follow the last pose.
/// Throws std::invalid_argument for a variable type with no g2o vertex (SO2, SO3, Point3), an edge or fixed key
/// without a value, a plain and a pose key with the same id, or a non-finite number. Writes to `path`.tmp and
/// renames it into place, so `path` is complete or untouched.
void writeG2o(const std::string& path, const FactorGraph& graph, const Values& values,
              const std::vector<Key>& fixed = {});

}  // namespace semslam
