#include "image_format_override.hpp"

#include "compile_error.hpp"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <algorithm>
#include <set>

namespace iblkit::compiler {
namespace {

std::string knownFormatNames() {
    std::string names;
    for (int f = glslang::ElfNone + 1; f < glslang::ElfExtSizeGuard; ++f) {
        const std::string name = glslang::TQualifier::getLayoutFormatString(static_cast<glslang::TLayoutFormat>(f));
        if (name != "none") names += (names.empty() ? "" : ", ") + name;
    }
    return names;
}

glslang::TLayoutFormat parseFormat(const std::string& name, const std::string& sourceName) {
    for (int f = glslang::ElfNone + 1; f < glslang::ElfExtSizeGuard; ++f)
        if (name == glslang::TQualifier::getLayoutFormatString(static_cast<glslang::TLayoutFormat>(f)))
            return static_cast<glslang::TLayoutFormat>(f);
    throw CompileError(sourceName + ": error: unknown image format '" + name + "' (known: " + knownFormatNames() + ")");
}

int channelCount(glslang::TLayoutFormat format) {
    std::string name = glslang::TQualifier::getLayoutFormatString(format);
    if (auto at = name.find("_snorm"); at != std::string::npos) name.erase(at);
    return static_cast<int>(std::count_if(name.begin(), name.end(), [](char c) {
        return c == 'r' || c == 'g' || c == 'b' || c == 'a';
    }));
}

glslang::TBasicType componentType(glslang::TLayoutFormat format) {
    if (format < glslang::ElfFloatGuard) return glslang::EbtFloat;
    if (format < glslang::ElfIntGuard) return glslang::EbtInt;
    return glslang::EbtUint;
}

class FormatSetter : public glslang::TIntermTraverser {
public:
    FormatSetter(std::map<std::string, glslang::TLayoutFormat> formats, std::string sourceName)
        : formats_(std::move(formats)), sourceName_(std::move(sourceName)) {}

    void visitSymbol(glslang::TIntermSymbol* symbol) override {
        const auto it = formats_.find(symbol->getName().c_str());
        if (it == formats_.end()) return;
        glslang::TType& type = symbol->getWritableType();
        check(it->first, type, it->second);
        type.getQualifier().layoutFormat = it->second;
        found_.insert(it->first);
    }

    void requireAllFound() const {
        for (const auto& [name, format] : formats_)
            if (!found_.count(name))
                throw CompileError(sourceName_ + ": error: --image-format names '" + name +
                                   "', which the entry point does not use as a storage image");
    }

private:
    void check(const std::string& name, const glslang::TType& type, glslang::TLayoutFormat format) const {
        const std::string formatName = glslang::TQualifier::getLayoutFormatString(format);
        if (!type.isImage())
            throw CompileError(sourceName_ + ": error: --image-format names '" + name +
                               "', which is not a storage image (RWTexture*)");
        const auto& sampler = type.getSampler();
        if (static_cast<int>(sampler.getVectorSize()) < channelCount(format))
            throw CompileError(sourceName_ + ": error: image format " + formatName + " of '" + name + "' has " +
                               std::to_string(channelCount(format)) + " channels but its element type has " +
                               std::to_string(sampler.getVectorSize()));
        if (sampler.type != componentType(format))
            throw CompileError(sourceName_ + ": error: image format " + formatName + " of '" + name +
                               "' does not match the component type of its element (" +
                               glslang::TType::getBasicString(sampler.type) + ")");
    }

    std::map<std::string, glslang::TLayoutFormat> formats_;
    std::string sourceName_;
    std::set<std::string> found_;
};

} // namespace

void overrideImageFormats(glslang::TIntermediate& intermediate, const std::map<std::string, std::string>& formats,
                          const std::string& sourceName) {
    if (formats.empty()) return;
    std::map<std::string, glslang::TLayoutFormat> parsed;
    for (const auto& [name, format] : formats) parsed[name] = parseFormat(format, sourceName);
    FormatSetter setter(std::move(parsed), sourceName);
    intermediate.getTreeRoot()->traverse(&setter);
    setter.requireAllFound();
}

} // namespace iblkit::compiler
