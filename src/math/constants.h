// Mathematical constants for host and per-ray code.
#pragma once

namespace urbis {

constexpr float kPi = 3.14159265358979323846f;

} // namespace urbis
