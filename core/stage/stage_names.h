#pragma once

// The scan's reconstruction stages on the bus: who runs each, and the files they hand on that
// only they read. The orchestrator names jobs by these; the services serve them.

namespace avc::stage {

inline constexpr char kBuildStage[] = "build";
inline constexpr char kBuildService[] = "avc-builder";
inline constexpr char kClusterStage[] = "cluster";
inline constexpr char kClusterService[] = "avc-clusterer";
inline constexpr char kSurfaceStage[] = "surface";
inline constexpr char kSurfaceService[] = "avc-surfacer";

// The cluster stage's clusters_t message, the surface stage's input (clusters.ply is for people
// and viewers and keeps fewer fields).
inline constexpr char kClustersMessageFile[] = "clusters.lcm";

}  // namespace avc::stage
