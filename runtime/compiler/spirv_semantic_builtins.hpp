#pragma once

namespace iblkit::compiler {

class SpirvModule;

// System values glslang's HLSL frontend does not know (SV_ViewID, SV_ShadingRate) reach its
// SPIR-V as user varyings at a Location, which clash with the shader's own (two inputs at
// location 0). Each becomes the built-in it names (ViewIndex; ShadingRateKHR as a pixel
// shader's input, PrimitiveShadingRateKHR as an earlier stage's output), found by the
// UserSemantic decoration glslang writes under hlsl_functionality1. Returns whether it changed
// the module.
bool semanticsAsBuiltIns(SpirvModule& module);

} // namespace iblkit::compiler

namespace iblkit::compiler {

// An array member of a varying struct with a [[vk::location(L)]] (a vertex shader's output
// `float weights[4]`), which glslang flattens into one variable per element, gives every element
// location L; they clash. Element k takes L plus the locations of the k before it, as the array
// would occupy them. Only a run of variables at one location whose names are one array's
// elements in order is renumbered, and never an array over vertices (a hull shader's output),
// which glslang flattens wrongly. Returns whether it changed the module.
bool flattenedArrayLocations(SpirvModule& module);

} // namespace iblkit::compiler
