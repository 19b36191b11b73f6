#include "vulkan_attributes.hpp"

#include "token_edit.hpp"

#include <charconv>
#include <set>

namespace iblkit::lowering {
namespace {

const std::set<std::string, std::less<>> kHonoured{"binding", "image_format", "push_constant", "constant_id", "location"};

// tokens[at] and tokens[at + 1] are "[" "[": the attribute list's closing "]" "]".
bool opensAttributeList(TokenSpan tokens, size_t at) {
    return at + 2 < tokens.size() && tokens[at].is("[") && tokens[at + 1].is("[") && tokens[at + 2].is("vk") &&
           tokens[at + 1].leading.empty();
}

uint32_t integerArgument(const Token& token, const std::string& attribute) {
    uint32_t value = 0;
    const auto [end, error] = std::from_chars(token.text.data(), token.text.data() + token.text.size(), value);
    if (token.kind != TokenKind::Number || error != std::errc() || end != token.text.data() + token.text.size())
        refuse(token, "[[vk::" + attribute + "]] takes whole numbers, not '" + token.text + "'");
    return value;
}

// The resource a declaration declares: "cbuffer NAME", or the last name before ':', ';',
// '[', '=' or '{' at depth 0.
const Token* declaredName(TokenSpan tokens, size_t begin) {
    const Token* name = nullptr;
    for (size_t i = begin; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        if (token.is("cbuffer") || token.is("tbuffer")) return i + 1 < tokens.size() && tokens[i + 1].isIdentifier() ? &tokens[i + 1] : nullptr;
        if (token.is("[") && i + 1 < tokens.size() && tokens[i + 1].is("[")) { // another attribute list
            i = matchingClose(tokens, i);
            continue;
        }
        if (token.is(":") || token.is(";") || token.is("[") || token.is("=") || token.is("{") || token.is("(")) return name;
        if (token.is("<")) {
            int depth = 0;
            for (; i < tokens.size(); ++i) {
                if (tokens[i].is("<")) ++depth;
                if (tokens[i].is(">") && --depth == 0) break;
                if (tokens[i].is(">>") && (depth -= 2) <= 0) break;
            }
            continue;
        }
        if (token.isIdentifier()) name = &token;
    }
    return name;
}

class AttributeReader {
public:
    AttributeReader(TokenSpan tokens, VulkanAttributes& attributes) : tokens_(tokens), attributes_(attributes) {}

    std::vector<Token> run() {
        for (size_t i = 0; i < tokens_.size(); ++i) {
            if (opensAttributeList(tokens_, i)) i = readList(i);
            else writer_.keep(tokens_[i]);
        }
        return writer_.finish();
    }

private:
    // Returns the index of the list's last "]".
    size_t readList(size_t at) {
        const size_t close = matchingClose(tokens_, at + 1);
        if (close + 1 >= tokens_.size() || !tokens_[close + 1].is("]")) refuse(tokens_[at], "an attribute list '[[' without ']]'");
        const Token* target = declaredName(tokens_, close + 2);
        std::vector<std::pair<size_t, size_t>> kept;
        for (const auto& [first, last] : splitAtCommas(tokens_, at + 2, close))
            if (read(first, last, target)) kept.emplace_back(first, last);
        if (kept.empty()) {
            writer_.drop(tokens_.subspan(at, close + 2 - at));
            return close + 1;
        }
        writer_.keep(tokens_.subspan(at, 2));
        for (size_t n = 0; n < kept.size(); ++n) {
            if (n > 0) writer_.add(",", tokens_[kept[n].first].place, "");
            writer_.keep(tokens_.subspan(kept[n].first, kept[n].second - kept[n].first));
        }
        writer_.keep(tokens_.subspan(close, 2));
        if (pushConstant_) return wrapPushConstant(close + 2);
        return close + 1;
    }

    // `[[vk::push_constant]] S pc;` declares push constants only as a ConstantBuffer<S> to
    // glslang. Returns the last index used.
    size_t wrapPushConstant(size_t at) {
        pushConstant_ = false;
        if (at + 2 >= tokens_.size()) return at - 1;
        const Token& type = tokens_[at];
        if (type.is("struct")) refuse(type, "[[vk::push_constant]] on a struct definition: define the struct, then declare "
                                            "'[[vk::push_constant]] ConstantBuffer<S> name;'");
        const bool plainStruct = type.isIdentifier() && !type.is("ConstantBuffer") && !type.is("cbuffer") &&
                                 tokens_[at + 1].isIdentifier() && tokens_[at + 2].is(";");
        if (!plainStruct) return keepWithoutRegister(at);
        writer_.add("ConstantBuffer<" + type.text + ">", type.place, type.leading);
        attributes_.pushConstantStructs = true;
        return at;
    }

    // A push-constant ConstantBuffer<S> or cbuffer may carry the register its Direct3D build
    // binds it to; DXC ignores it for Vulkan, and glslang would decorate the block with a set and
    // binding that push constants cannot have. Keeps the declaration up to its ";" or "{" without
    // its ": register(...)"; returns the last index kept.
    size_t keepWithoutRegister(size_t at) {
        size_t i = at;
        for (; i < tokens_.size() && !tokens_[i].is(";") && !tokens_[i].is("{"); ++i) {
            if (tokens_[i].is(":") && i + 2 < tokens_.size() && tokens_[i + 1].is("register") && tokens_[i + 2].is("(")) {
                const size_t close = matchingClose(tokens_, i + 2);
                writer_.drop(tokens_.subspan(i, close + 1 - i));
                i = close;
                continue;
            }
            writer_.keep(tokens_[i]);
        }
        return i - 1;
    }

    // One "vk::name(arguments)" of a list: whether glslang is to see it.
    bool read(size_t first, size_t last, const Token* target) {
        if (last - first < 3 || !tokens_[first].is("vk") || !tokens_[first + 1].is("::") || !tokens_[first + 2].isIdentifier())
            return true; // not a vk:: attribute: glslang's to judge
        const Token& name = tokens_[first + 2];
        std::vector<std::pair<size_t, size_t>> arguments;
        if (first + 3 < last && tokens_[first + 3].is("(")) arguments = splitAtCommas(tokens_, first + 4, matchingClose(tokens_, first + 3));
        if (!kHonoured.contains(name.text)) {
            attributes_.warnings.push_back(name.place.describe() + ": warning: [[vk::" + name.text +
                                           "]] is not honoured by the kit (it honours vk::" +
                                           "binding, image_format, push_constant, constant_id and location)");
            return true;
        }
        if (name.text == "binding") return readBinding(name, arguments, target);
        if (name.text == "image_format") return readImageFormat(name, arguments, target);
        if (name.text == "push_constant") pushConstant_ = true;
        return true;
    }

    bool readBinding(const Token& name, const std::vector<std::pair<size_t, size_t>>& arguments, const Token* target) {
        if (!target) refuse(name, "[[vk::binding]] stands before no resource declaration");
        if (arguments.empty() || arguments.size() > 2) refuse(name, "[[vk::binding]] takes (binding) or (binding, set)");
        for (const auto& [begin, end] : arguments)
            if (end != begin + 1) refuse(tokens_[begin], "[[vk::binding]] takes whole numbers");
        VulkanBinding binding{integerArgument(tokens_[arguments[0].first], "binding"),
                              arguments.size() == 2 ? integerArgument(tokens_[arguments[1].first], "binding") : 0,
                              name.place};
        attributes_.bindings[target->text] = binding;
        return true;
    }

    bool readImageFormat(const Token& name, const std::vector<std::pair<size_t, size_t>>& arguments, const Token* target) {
        if (!target) refuse(name, "[[vk::image_format]] stands before no resource declaration");
        if (arguments.size() != 1 || arguments[0].second != arguments[0].first + 1 ||
            tokens_[arguments[0].first].kind != TokenKind::String)
            refuse(name, "[[vk::image_format]] takes one format name in quotes, as in (\"rgba8\")");
        const std::string& quoted = tokens_[arguments[0].first].text;
        attributes_.imageFormats[target->text] = quoted.substr(1, quoted.size() - 2);
        return false;
    }

    TokenSpan tokens_;
    VulkanAttributes& attributes_;
    TokenWriter writer_;
    bool pushConstant_ = false;
};

} // namespace

std::vector<Token> readVulkanAttributes(const std::vector<Token>& tokens, VulkanAttributes& attributes) {
    return AttributeReader(tokens, attributes).run();
}

} // namespace iblkit::lowering
