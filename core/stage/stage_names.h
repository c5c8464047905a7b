#pragma once

// The scan's stages on the bus (planning and the reconstruction): who runs each, and the files they
// hand on that only they read. The orchestrator names jobs by these; the services serve them.

namespace avc::stage {

inline constexpr char kBuildStage[] = "build";
inline constexpr char kBuildService[] = "avc-builder";
inline constexpr char kClusterStage[] = "cluster";
inline constexpr char kClusterService[] = "avc-clusterer";
inline constexpr char kSurfaceStage[] = "surface";
inline constexpr char kSurfaceService[] = "avc-surfacer";
// The scan's views: one plan job per view (core/plan/plan_exchange.h).
inline constexpr char kPlanStage[] = "plan";
inline constexpr char kPlanService[] = "avc-planner";

// The cluster stage's clusters_t message, the surface stage's input (clusters.ply is for people
// and viewers and keeps fewer fields).
inline constexpr char kClustersMessageFile[] = "clusters.lcm";

}  // namespace avc::stage
