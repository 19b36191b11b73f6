#pragma once

#include <string_view>

namespace iblkit::compiler {

// What one of the kit's edits does, by the id CompiledShader::kitEdits names it with
// ("select-and-or", "texel-widening", ...); empty for an id the kit does not have.
std::string_view describeKitEdit(std::string_view id);

} // namespace iblkit::compiler
