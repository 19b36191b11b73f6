#include "lowering.hpp"

#include "builtin_structs.hpp"
#include "byte_address_dimensions.hpp"
#include "enums.hpp"
#include "intrinsics.hpp"
#include "namespaces.hpp"
#include "partial_texel_writes.hpp"
#include "non_uniform_index.hpp"
#include "refusals.hpp"
#include "resource_locals.hpp"
#include "sixteen_bit.hpp"
#include "struct_conversions.hpp"
#include "struct_scope.hpp"
#include "templates.hpp"
#include "type_spellings.hpp"
#include "unreachable_declarations.hpp"
#include "unsupported_features.hpp"

#include <algorithm>

namespace iblkit::lowering {
namespace {

bool sameText(const std::vector<Token>& a, const std::vector<Token>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const Token& x, const Token& y) {
               return x.text == y.text;
           });
}

// Runs one pass and names it among the edits when it changed a token.
template <typename Pass>
std::vector<Token> runPass(const std::vector<Token>& tokens, const char* edit, std::vector<std::string>& edits, Pass pass) {
    auto lowered = pass(tokens);
    if (!sameText(tokens, lowered)) edits.emplace_back(edit);
    return lowered;
}

} // namespace

LoweredSource lowerHlsl(const std::string& preprocessed, const std::string& sourceName, HlslVersion version,
                        bool enable16BitTypes, const std::string& entryPoint) {
    LoweredSource lowered;
    auto& edits = lowered.edits;
    auto tokens = runPass(tokenize(preprocessed, sourceName), "type-spellings", edits, lowerTypeSpellings);
    tokens = runPass(tokens, "explicit-width-types", edits, [&](const auto& in) {
        return lowerSixteenBitTypes(in, enable16BitTypes, lowered.warnings);
    });
    tokens = runPass(tokens, "struct-scope-declarations", edits, hoistStructScopeDeclarations);
    if (version == HlslVersion::Hlsl2021) {
        tokens = runPass(tokens, "templates", edits, [&](const auto& in) { return lowerTemplates(in, enable16BitTypes); });
        tokens = lowerTypeSpellings(tokens); // vector<T, N> of an instance, its T now a scalar
        refuseUnlowerable(tokens);
    }
    // Enums and namespaces are older than HLSL 2021 (DXC takes them under -HV 2018); select, and
    // and or are 2021's, and in older code the names are a shader's own to use.
    tokens = runPass(tokens, "enums", edits, lowerEnums);
    tokens = runPass(tokens, "namespaces", edits, lowerNamespaces);
    tokens = runPass(tokens, "unreachable-declarations", edits,
                     [&](const auto& in) { return dropUnreachableUnsupported(in, entryPoint); });
    tokens = runPass(tokens, "builtin-structs", edits, declareBuiltinStructs);
    tokens = runPass(tokens, "non-uniform-resource-index", edits, lowerNonUniformResourceIndex);
    tokens = runPass(tokens, "resource-locals", edits, inlineResourceLocals);
    tokens = runPass(tokens, "partial-texel-writes", edits, lowerPartialTexelWrites);
    tokens = runPass(tokens, "storage-load-coordinates", edits, convertStorageLoadCoordinates);
    tokens = runPass(tokens, "struct-conversions", edits, convertReturnedStructs);
    tokens = runPass(tokens, "byte-address-dimensions", edits, scaleByteAddressDimensions);
    refuseUnsupportedFeatures(tokens);
    if (version == HlslVersion::Hlsl2021) tokens = runPass(tokens, "select-and-or", edits, lowerIntrinsics);
    for (size_t i = 0; i + 2 < tokens.size(); ++i)
        if (tokens[i].isIdentifier() && tokens[i + 1].is(":") && tokens[i + 2].is("packoffset")) lowered.packedMembers.insert(tokens[i].text);
    lowered.text = render(readVulkanAttributes(tokens, lowered.vulkan));
    if (!lowered.vulkan.bindings.empty()) edits.emplace_back("vk-binding");
    if (!lowered.vulkan.imageFormats.empty()) edits.emplace_back("vk-image-format");
    if (lowered.vulkan.pushConstantStructs) edits.emplace_back("vk-push-constant");
    lowered.warnings.insert(lowered.warnings.end(), lowered.vulkan.warnings.begin(), lowered.vulkan.warnings.end());
    lowered.changed = lowered.text != preprocessed;
    return lowered;
}

} // namespace iblkit::lowering
