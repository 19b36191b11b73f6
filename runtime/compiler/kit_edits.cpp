#include "kit_edits.hpp"

#include <array>
#include <utility>

namespace iblkit::compiler {
namespace {

// The source edits are runtime/lowering's passes; the SPIR-V edits are the spirv_*.cpp files here.
constexpr std::array<std::pair<std::string_view, std::string_view>, 27> kKitEdits{{
    {"resource-locals", "a local variable holding a resource (ByteAddressBuffer b = Buffers[i];) is replaced by its value at each use, when nothing that value reads is assigned later in its block"},
    {"struct-scope-declarations", "a struct's static members with their values and its enums move to a namespace of the struct's name (S::Name, then S__Name)"},
    {"non-uniform-resource-index", "NonUniformResourceIndex(i) becomes (i), and every access into an array of resources at a run-time index is decorated NonUniform (conservative: glslang's SPIR-V no longer tells one index from another)"},
    {"type-spellings", "vector<T, N> and matrix<T, R, C> of any scalar become TN and TRxC, minimum-precision matrices (min16float3x3) half3x3, swizzled literals (1.xxxx) (1.0).xxxx, and unsigned int becomes uint"},
    {"unreachable-declarations", "functions the entry point never reaches, and declarations it never reaches that hold a feature glslang lacks (ray tracing in a shared header), are dropped, as DXC drops them"},
    {"partial-texel-writes", "a write to some components of a storage texel (Output[xy].rgb = c;) becomes a read of "
                             "the texel, the components written, and the texel stored back, as DXC compiles it"},
    {"storage-load-coordinates", "a storage texture's Load given coordinates of another length (Image.Load(int3(xy, 0)) "
                                 "on a RWTexture2D) converts them to the texture's, as DXC truncates them"},
    {"struct-conversions", "a struct returned as another struct of the same member types (return input; from a "
                           "vertex shader) becomes that conversion, member by member"},
    {"byte-address-dimensions", "a byte-address buffer's GetDimensions, which glslang answers in 32-bit words, is "
                                "multiplied by 4 to the bytes Direct3D answers ({ B.GetDimensions(n); n *= 4u; })"},
    {"builtin-structs", "DXR's RayDesc and BuiltInTriangleIntersectionAttributes, used outside ray tracing, are "
                        "declared as the HLSL specification defines them"},
    {"templates", "function and struct templates become one function or struct per argument list (f<float> and a call "
                  "whose arguments deduce float: f__float), and sizeof(type) its size in bytes"},
    {"select-and-or", "select, and and or become component-wise ?:, && and ||"},
    {"enums", "enums become a typedef of their underlying type and one constant per enumerator"},
    {"namespaces", "namespaces become name prefixes (N__name), with C++ lookup; using aliases become typedefs"},
    {"explicit-width-types", "Shader Model 6.2 explicit-width types under glslang's names: float16_t, int16_t and uint16_t become half, min16int and min16uint; float32_t, int32_t, uint32_t and float64_t become float, int, uint and double"},
    {"vk-binding", "[[vk::binding(b, s)]] sets the set and binding, instead of the register rule"},
    {"vk-image-format", "[[vk::image_format]] sets the storage image's format, which glslang ignores"},
    {"vk-push-constant", "[[vk::push_constant]] S name; becomes a push-constant ConstantBuffer<S>"},
    {"texel-widening", "image writes narrower than the format are widened to four components (VUID-07112)"},
    {"exclusive-wave-scans", "WavePrefix* scans are made exclusive (glslang emits them inclusive: glslang issue 2929)"},
    {"image-access-qualifiers", "storage images only written or only read are decorated NonReadable or NonWritable"},
    {"atomic-value-types", "an atomic's int value for a uint result (or the reverse) is reinterpreted as the result's type, "
                           "which glslang leaves invalid"},
    {"flat-integer-inputs", "integer and double pixel-shader inputs are decorated Flat (VUID-04744), which glslang "
                            "leaves off built-ins such as WaveGetLaneIndex()"},
    {"semantic-built-ins", "SV_ViewID and SV_ShadingRate, which glslang makes user varyings at a location, become the "
                           "built-ins they name (ViewIndex, ShadingRateKHR or PrimitiveShadingRateKHR)"},
    {"flattened-array-locations", "an array varying at [[vk::location(L)]] that glslang splits into one variable per "
                                  "element, each at L, takes L, L+1, ... as the array would"},
    {"boolean-logic", "bitwise |, & and ^ of bools (and ~) become the logical operations SPIR-V allows on booleans, "
                      "which glslang writes as integer ones"},
    {"constant-image-offsets", "a texture offset that is a constant once legalized (passed through a function "
                               "parameter) becomes a constant offset, which Vulkan requires outside gathers"},
}};

} // namespace

std::string_view describeKitEdit(std::string_view id) {
    for (const auto& [name, description] : kKitEdits)
        if (name == id) return description;
    return {};
}

} // namespace iblkit::compiler
