#pragma once
// The cleanup's thresholds (paper §2.5). They select which edits are proposed and how far a
// face may turn before the exact tests run; no validity decision rests on them.
#include <cstddef>

namespace molsurf::surface_cleanup {

inline constexpr double kSameTagFlipCos = 0.9;    // a flip's faces: within 26 degrees of each other
inline constexpr double kCrossTagFlipCos = 0.94;  // across a seam: within 20 degrees
inline constexpr double kClusterFraction = 0.2;   // a cluster's edges: under this part of the sliver's middle edge
inline constexpr std::size_t kMaxCluster = 8;
inline constexpr std::size_t kMaxUnblockSteps = 3;  // edits that may clear the way for a collapse
inline constexpr double kSmallestNewAngle = 1e-3;   // degrees; no change makes a face thinner
inline constexpr double kSmoothCos = 0.87;  // a vertex moves only if its faces are within 30 degrees of their sum
inline constexpr double kNeckFraction = 0.5;  // a neck's loop: edges under this part of the sliver's longest
inline constexpr double kNeckWidth = 0.5;     // it widens to this part of the edges leaving it
inline constexpr double kCapHeight = 0.02;    // a cap: its apex within this part of its base's length (about 1 degree)
inline constexpr double kMinOpeningDeg = 1;   // no edit folds two faces on an edge closer than this
inline constexpr double kMaxTurnCos = 0.5;    // no new face turns more than 60 degrees from its reference
inline constexpr double kShortEdgeFraction = 0.6;  // an edge a collapse may remove: under this part of the face's longest

}  // namespace molsurf::surface_cleanup
