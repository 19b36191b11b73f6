#pragma once

#include <cstdint>

namespace iblkit::numeric {

// IEEE 754 binary16 as Imath converts it: round to nearest even, overflow to infinity, NaN kept
// a NaN. (Compilers disagree on whether _Float16 exists, so the kit does not use it.)
uint16_t toHalfBits(float value);
float fromHalfBits(uint16_t bits);

// A value rounded to the nearest half and back.
inline float roundedToHalf(float value) { return fromHalfBits(toHalfBits(value)); }

} // namespace iblkit::numeric
