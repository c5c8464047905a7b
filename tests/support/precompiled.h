// The headers nearly every test parses, precompiled once for all of them (cmake/AvcTargets.cmake,
// avc_add_test): gtest, Eigen, OpenCV's core, nlohmann::json and the standard library. They hold
// no macros our code sets, so one precompiled copy is valid for every test.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>
