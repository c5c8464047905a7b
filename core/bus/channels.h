#pragma once

// Channel names without the cell prefix (the bus adds "<cell>/"). One message type per channel;
// lcmtypes/CHANNELS.md is the table of types, producers and consumers and must list every name
// here (tests/core/channels_test.cc checks it).

#include <array>
#include <string_view>

namespace avc::channels {

inline constexpr std::string_view kHeartbeat = "HEARTBEAT";
inline constexpr std::string_view kLog = "LOG";
inline constexpr std::string_view kProgress = "PROGRESS";
inline constexpr std::string_view kAck = "ACK";
inline constexpr std::string_view kConfig = "CONFIG";
inline constexpr std::string_view kRunInfo = "RUN_INFO";
inline constexpr std::string_view kProcessStatus = "PROCESS_STATUS";
inline constexpr std::string_view kRobotState = "ROBOT_STATE";
inline constexpr std::string_view kRobotCommand = "ROBOT_COMMAND";
inline constexpr std::string_view kTurntableState = "TURNTABLE_STATE";
inline constexpr std::string_view kTurntableCommand = "TURNTABLE_COMMAND";
inline constexpr std::string_view kCaptureRequest = "CAPTURE_REQUEST";
inline constexpr std::string_view kCamera = "CAMERA";
inline constexpr std::string_view kCameraQuery = "CAMERA_QUERY";
inline constexpr std::string_view kCalibration = "CALIBRATION";
inline constexpr std::string_view kOrchestratorState = "ORCH_STATE";
inline constexpr std::string_view kScanCameras = "SCAN_CAMERAS";
inline constexpr std::string_view kProductAck = "PRODUCT_ACK";
inline constexpr std::string_view kBuildCommand = "BUILD_COMMAND";
// Product channels (bulk URL, product_chunk_t).
inline constexpr std::string_view kProductImage = "PRODUCT/IMAGE";
inline constexpr std::string_view kProductPreview = "PRODUCT/PREVIEW";
inline constexpr std::string_view kProductCloud = "PRODUCT/CLOUD";
inline constexpr std::string_view kProductMesh = "PRODUCT/MESH";
inline constexpr std::string_view kProductVoxelMap = "PRODUCT/VOXEL_MAP";
inline constexpr std::string_view kProductBench = "PRODUCT/BENCH";
inline constexpr std::string_view kProductMvsPoints = "PRODUCT/MVS_POINTS";
inline constexpr std::string_view kProductClusters = "PRODUCT/CLUSTERS";
inline constexpr std::string_view kProductStageJob = "PRODUCT/STAGE_JOB";
inline constexpr std::string_view kProductStageResult = "PRODUCT/STAGE_RESULT";
// Prefix shared by every product channel.
inline constexpr std::string_view kProductPrefix = "PRODUCT/";

inline constexpr std::array kAll = {kHeartbeat,
                                    kLog,
                                    kProgress,
                                    kAck,
                                    kConfig,
                                    kRunInfo,
                                    kProcessStatus,
                                    kRobotState,
                                    kRobotCommand,
                                    kTurntableState,
                                    kTurntableCommand,
                                    kCaptureRequest,
                                    kCamera,
                                    kCameraQuery,
                                    kCalibration,
                                    kOrchestratorState,
                                    kScanCameras,
                                    kProductAck,
                                    kBuildCommand,
                                    kProductImage,
                                    kProductPreview,
                                    kProductCloud,
                                    kProductMesh,
                                    kProductVoxelMap,
                                    kProductBench,
                                    kProductMvsPoints,
                                    kProductClusters,
                                    kProductStageJob,
                                    kProductStageResult};

}  // namespace avc::channels
