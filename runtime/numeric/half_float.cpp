#include "half_float.hpp"

#include <Imath/half.h>

namespace iblkit::numeric {

uint16_t toHalfBits(float value) { return imath_float_to_half(value); }

float fromHalfBits(uint16_t bits) { return imath_half_to_float(bits); }

} // namespace iblkit::numeric
