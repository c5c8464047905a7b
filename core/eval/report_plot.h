#pragma once

// A small picture of an evaluation for people: histograms of the accuracy (reconstruction →
// ground truth) and completeness (ground truth → reconstruction) distances, and precision,
// recall and F-score against the threshold. Drawn with OpenCV; same result → same PNG bytes.

#include <cstdint>
#include <vector>

#include "core/eval/metrics.h"

namespace avc::eval {

std::vector<uint8_t> RenderErrorPlotPng(const EvalResult& result);

}  // namespace avc::eval
