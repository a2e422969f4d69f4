// One SVG picture of a reconstruction a person can read: the input points (grey), the curve
// (black), the interior medial axis (blue) and the dominant points (red rings).
// In: the input points and a reconstruction whose indices refer to them. Out: SVG text.
#pragma once

#include <span>
#include <string>

#include "core/reconstruction.h"

namespace curvebench {

std::string reconstruction_svg(std::span<const Point2> points, const Reconstruction& result, const std::string& title);

}  // namespace curvebench
