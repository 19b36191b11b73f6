#include "templates.hpp"

#include "token_edit.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace iblkit::lowering {
namespace {

struct TemplateParameter {
    std::string name;
    bool isType = true; // typename T or class T; otherwise a constant (uint N)
};

struct Template {
    size_t begin = 0, end = 0; // "template" ... the end of the declaration
    size_t declaration = 0;    // the first token after the parameter list's ">"
    size_t name = 0;           // the declared name
    bool isStruct = false;
    std::vector<TemplateParameter> parameters;
    std::vector<std::vector<std::string>> parameterTypes; // a function's, as token texts
};

// ---- types -------------------------------------------------------------------------------

constexpr std::string_view kScalars[] = {"bool",       "int",      "uint",      "dword",    "half",     "float",
                                         "double",     "min16float", "min16int", "min16uint", "min10float", "min12int",
                                         "int64_t",    "uint64_t", "float16_t", "int16_t",  "uint16_t", "float32_t",
                                         "int32_t",    "uint32_t", "float64_t"};

// "float3x4" -> {"float", 3, 4}; "uint2" -> {"uint", 2, 1}; "half" -> {"half", 1, 1}.
struct Shape {
    std::string scalar;
    int rows = 1, columns = 1;
};

std::optional<Shape> builtinShape(const std::string& name) {
    for (const auto scalar : kScalars) {
        if (name.rfind(scalar, 0) != 0) continue;
        const std::string suffix = name.substr(scalar.size());
        if (suffix.empty()) return Shape{std::string(scalar), 1, 1};
        const auto digit = [](char c) { return c >= '1' && c <= '4'; };
        if (suffix.size() == 1 && digit(suffix[0])) return Shape{std::string(scalar), suffix[0] - '0', 1};
        if (suffix.size() == 3 && digit(suffix[0]) && suffix[1] == 'x' && digit(suffix[2]))
            return Shape{std::string(scalar), suffix[0] - '0', suffix[2] - '0'};
    }
    return std::nullopt;
}

bool isBuiltinType(const std::string& name) { return builtinShape(name).has_value(); }

std::string literalType(const Token& token) {
    const std::string& text = token.text;
    const bool real = text.find_first_of(".eE") != std::string::npos && text.rfind("0x", 0) != 0;
    const char last = char(std::tolower(static_cast<unsigned char>(text.back())));
    if (real || last == 'f' || last == 'h' || last == 'l') {
        if (last == 'h') return "half";
        if (last == 'l') return "double";
        return "float";
    }
    return last == 'u' ? "uint" : "int";
}

// ---- structure of the token list ---------------------------------------------------------

// For each token, where the top-level declaration that holds it starts.
std::vector<size_t> topLevelStarts(const std::vector<Token>& tokens) {
    std::vector<size_t> starts(tokens.size(), 0);
    size_t start = 0;
    int depth = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (depth == 0 && i > 0 && (tokens[i - 1].is(";") || (tokens[i - 1].is("}") && !tokens[i].is(";")) ||
                                    tokens[i - 1].kind == TokenKind::Directive))
            start = i;
        starts[i] = start;
        if (opensBracket(tokens[i])) ++depth;
        if (closesBracket(tokens[i])) depth = std::max(0, depth - 1);
    }
    return starts;
}

size_t closingAngle(const std::vector<Token>& tokens, size_t open) {
    int depth = 0;
    for (size_t i = open; i < tokens.size(); ++i) {
        if (tokens[i].is("<")) ++depth;
        if (tokens[i].is(">") && --depth == 0) return i;
        if (tokens[i].is(">>") && (depth -= 2) <= 0) return i;
        if (tokens[i].is(";") || tokens[i].is("{")) break;
    }
    refuse(tokens[open], "a template argument list that does not end: write it as '<' arguments '>'");
}

std::vector<std::string> texts(TokenSpan tokens) {
    std::vector<std::string> out;
    for (const auto& token : tokens) out.push_back(token.text);
    return out;
}

// ---- reading templates -------------------------------------------------------------------

// The ranges between the commas of a declaration's list at depth 0, counting "<" and ">" as
// brackets: a parameter typed Ring<T, 4>, an argument Pair<float, 2>.
std::vector<std::pair<size_t, size_t>> splitDeclarationList(const std::vector<Token>& tokens, size_t begin, size_t end) {
    std::vector<std::pair<size_t, size_t>> ranges;
    int depth = 0;
    size_t start = begin;
    for (size_t i = begin; i < end; ++i) {
        if (opensBracket(tokens[i]) || tokens[i].is("<")) ++depth;
        if (closesBracket(tokens[i]) || tokens[i].is(">")) --depth;
        if (tokens[i].is(">>")) depth -= 2;
        if (depth == 0 && tokens[i].is(",")) {
            ranges.emplace_back(start, i);
            start = i + 1;
        }
    }
    if (end > start) ranges.emplace_back(start, end);
    return ranges;
}

std::vector<TemplateParameter> readParameters(const std::vector<Token>& tokens, size_t open, size_t close) {
    std::vector<TemplateParameter> parameters;
    for (const auto& [begin, end] : splitDeclarationList(tokens, open + 1, close)) {
        if (end - begin != 2 || !tokens[end - 1].isIdentifier())
            refuse(tokens[begin], "a template parameter the kit cannot instantiate (a default argument, or a template "
                                  "template parameter): write 'typename T' or a constant such as 'uint N'");
        const bool isType = tokens[begin].is("typename") || tokens[begin].is("class");
        if (!isType && !isBuiltinType(tokens[begin].text))
            refuse(tokens[begin], "a template parameter of type '" + tokens[begin].text + "': the kit instantiates type "
                                  "parameters and scalar constants");
        parameters.push_back({tokens[end - 1].text, isType});
    }
    return parameters;
}

std::vector<std::vector<std::string>> readFunctionParameterTypes(const std::vector<Token>& tokens, size_t open, size_t close) {
    static const std::set<std::string, std::less<>> kQualifiers{"in",      "out",       "inout",   "const",  "uniform",
                                                                "precise", "nointerpolation", "linear", "noperspective",
                                                                "centroid", "sample"};
    std::vector<std::vector<std::string>> types;
    for (auto [begin, end] : splitDeclarationList(tokens, open + 1, close)) {
        while (begin < end && kQualifiers.contains(tokens[begin].text)) ++begin;
        size_t nameAt = end;
        for (size_t k = begin; k < end; ++k)
            if (tokens[k].is(":") || tokens[k].is("=") || tokens[k].is("[")) {
                nameAt = k;
                break;
            }
        if (nameAt > begin) --nameAt; // the parameter's name
        types.push_back(texts(TokenSpan(tokens).subspan(begin, nameAt - begin)));
    }
    return types;
}

std::optional<Template> readTemplate(const std::vector<Token>& tokens, size_t at) {
    if (!tokens[at].is("template") || at + 1 >= tokens.size() || !tokens[at + 1].is("<")) return std::nullopt;
    Template found;
    found.begin = at;
    const size_t close = closingAngle(tokens, at + 1);
    if (close == at + 2)
        refuse(tokens[at], "an explicit specialization (template <>) cannot be lowered: give the specialized function "
                           "its own name");
    found.parameters = readParameters(tokens, at + 1, close);
    found.declaration = close + 1;
    size_t k = found.declaration;
    if (tokens[k].is("struct") || tokens[k].is("class")) {
        found.isStruct = true;
        found.name = k + 1;
        while (k < tokens.size() && !tokens[k].is("{")) ++k;
        found.end = matchingClose(tokens, k) + 1;
        if (found.end < tokens.size() && tokens[found.end].is(";")) ++found.end;
        return found;
    }
    while (k < tokens.size() && !tokens[k].is("(") && !tokens[k].is(";") && !tokens[k].is("{")) ++k;
    if (k >= tokens.size() || !tokens[k].is("(") || k == found.declaration || !tokens[k - 1].isIdentifier())
        refuse(tokens[at], "a template the kit cannot read: it instantiates function and struct templates");
    found.name = k - 1;
    const size_t parametersClose = matchingClose(tokens, k);
    found.parameterTypes = readFunctionParameterTypes(tokens, k, parametersClose);
    size_t body = parametersClose + 1;
    while (body < tokens.size() && !tokens[body].is("{") && !tokens[body].is(";")) ++body;
    if (body >= tokens.size() || !tokens[body].is("{"))
        refuse(tokens[found.name], "a template declared without its body: define it where it is declared");
    found.end = matchingClose(tokens, body) + 1;
    return found;
}

std::string mangled(const std::string& name, const std::vector<std::string>& arguments) {
    std::string out = name;
    for (const auto& argument : arguments) {
        out += "__";
        for (const char c : argument)
            if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') out += c;
            else if (c == '-') out += "minus";
    }
    return out;
}

// ---- the types of what a call passes -----------------------------------------------------

class DeclaredTypes {
public:
    explicit DeclaredTypes(const std::vector<Token>& tokens) : tokens_(tokens) {
        for (size_t i = 1; i < tokens.size(); ++i)
            if ((tokens[i - 1].is("struct") || tokens[i - 1].is("class")) && tokens[i].isIdentifier()) {
                structs_.insert(tokens[i].text);
                if (i + 1 < tokens.size() && tokens[i + 1].is("{")) bodies_[tokens[i].text] = i + 1;
            }
    }

    // The type of a struct's member, declared in its body as "Type member;".
    std::optional<std::vector<std::string>> ofMember(const std::string& structName, const std::string& member) const {
        const auto body = bodies_.find(structName);
        if (body == bodies_.end()) return std::nullopt;
        const size_t close = matchingClose(tokens_, body->second);
        for (size_t k = body->second + 2; k < close; ++k)
            if (tokens_[k].is(member) && tokens_[k].isIdentifier() && isType(tokens_[k - 1].text) &&
                (tokens_[k + 1].is(";") || tokens_[k + 1].is(",") || tokens_[k + 1].is(":")))
                return std::vector<std::string>{tokens_[k - 1].text};
        return std::nullopt;
    }

    bool isType(const std::string& name) const { return isBuiltinType(name) || structs_.contains(name); }

    // The type `name` is declared with, nearest before `use` (a local or parameter of the
    // declaration that holds it, then a global), as token texts: {"float3"}, {"Pair", "<", "float", ">"}.
    std::optional<std::vector<std::string>> ofName(const std::string& name, size_t use) const {
        for (size_t k = use; k-- > 1;) {
            if (!tokens_[k].is(name) || !tokens_[k].isIdentifier() || k + 1 >= tokens_.size()) continue;
            const Token& next = tokens_[k + 1];
            if (!(next.is("=") || next.is(";") || next.is(",") || next.is(")") || next.is(":") || next.is("["))) continue;
            if (isType(tokens_[k - 1].text)) return std::vector<std::string>{tokens_[k - 1].text};
            if (tokens_[k - 1].is(">")) {
                int depth = 0;
                for (size_t open = k - 1; open > 0; --open) {
                    if (tokens_[open].is(">")) ++depth;
                    if (tokens_[open].is("<") && --depth == 0) {
                        if (!tokens_[open - 1].isIdentifier()) break;
                        return texts(TokenSpan(tokens_).subspan(open - 1, k - open + 1));
                    }
                    if (tokens_[open].is(";") || tokens_[open].is("{") || tokens_[open].is("(")) break;
                }
            }
        }
        return std::nullopt;
    }

    // The type of tokens[begin, end) where it is plain: a literal, a name, a constructor, a cast,
    // a swizzle of a name.
    std::optional<std::vector<std::string>> ofExpression(size_t begin, size_t end) const {
        if (begin >= end) return std::nullopt;
        const Token& first = tokens_[begin];
        using Type = std::vector<std::string>;
        if (end - begin == 1) {
            if (first.kind == TokenKind::Number) return Type{literalType(first)};
            if (first.is("true") || first.is("false")) return Type{"bool"};
            if (first.isIdentifier()) return ofName(first.text, begin);
            return std::nullopt;
        }
        if (first.is("-") || first.is("+")) return ofExpression(begin + 1, end);
        if (isType(first.text) && tokens_[begin + 1].is("(") && matchingClose(tokens_, begin + 1) == end - 1) return Type{first.text};
        if (first.is("(") && begin + 2 < end && isType(tokens_[begin + 1].text) && tokens_[begin + 2].is(")"))
            return Type{tokens_[begin + 1].text};
        if (first.is("(") && matchingClose(tokens_, begin) == end - 1) return ofExpression(begin + 1, end - 1);
        if (end - begin == 3 && first.isIdentifier() && tokens_[begin + 1].is(".")) {
            const auto type = ofName(first.text, begin);
            const auto swizzle = type && type->size() == 1 ? swizzled((*type)[0], tokens_[begin + 2].text) : std::nullopt;
            if (swizzle) return Type{*swizzle};
            if (type) return ofMember(structName(*type), tokens_[begin + 2].text);
        }
        return std::nullopt;
    }

private:
    // {"Pair", "<", "float", ">"} -> "Pair__float", the instance's name; {"S"} -> "S".
    static std::string structName(const std::vector<std::string>& type) {
        if (type.size() < 4 || type[1] != "<" || type.back() != ">") return type.empty() ? "" : type[0];
        std::vector<std::string> arguments{""};
        for (size_t k = 2; k + 1 < type.size(); ++k)
            if (type[k] == ",") arguments.emplace_back();
            else arguments.back() += (arguments.back().empty() ? "" : " ") + type[k];
        return mangled(type[0], arguments);
    }

    static std::optional<std::string> swizzled(const std::string& type, const std::string& components) {
        if (components.size() > 4 || components.find_first_not_of("xyzwrgba") != std::string::npos) return std::nullopt;
        const auto shape = builtinShape(type);
        if (!shape || shape->columns != 1) return std::nullopt;
        return components.size() == 1 ? shape->scalar : shape->scalar + std::to_string(components.size());
    }

    const std::vector<Token>& tokens_;
    std::set<std::string> structs_;
    std::map<std::string, size_t> bodies_; // struct -> its "{"
};

// ---- instantiation -----------------------------------------------------------------------

// The template's arguments written at a use: NAME < a , b >.
std::vector<std::string> writtenArguments(const std::vector<Token>& tokens, size_t open, size_t close) {
    std::vector<std::string> arguments;
    for (const auto& [begin, end] : splitDeclarationList(tokens, open + 1, close))
        arguments.push_back(spacedText(TokenSpan(tokens).subspan(begin, end - begin)));
    return arguments;
}

// Binds the template parameters in a parameter's type to the argument's type, token by token
// (T to float, Pair<T> to Pair<float>), and vector<T, N> to a vector's scalar.
void unify(const std::vector<std::string>& parameter, const std::vector<std::string>& argument, const Template& templ,
           std::map<std::string, std::string>& deduced) {
    const auto isParameter = [&](const std::string& name) {
        return std::any_of(templ.parameters.begin(), templ.parameters.end(), [&](const auto& p) { return p.name == name; });
    };
    if (parameter.size() == 6 && parameter[0] == "vector" && parameter[1] == "<" && argument.size() == 1) {
        if (const auto shape = builtinShape(argument[0]); shape && isParameter(parameter[2])) deduced.emplace(parameter[2], shape->scalar);
        return;
    }
    if (parameter.size() != argument.size()) return;
    for (size_t k = 0; k < parameter.size(); ++k)
        if (isParameter(parameter[k])) deduced.emplace(parameter[k], argument[k]);
        else if (parameter[k] != argument[k]) return;
}

// A function template's arguments deduced from a call's, where each argument's type is plain.
std::vector<std::string> deducedArguments(const std::vector<Token>& tokens, const Template& templ, size_t open,
                                          const DeclaredTypes& types) {
    const auto arguments = splitAtCommas(tokens, open + 1, matchingClose(tokens, open));
    std::map<std::string, std::string> deduced;
    for (size_t p = 0; p < templ.parameterTypes.size() && p < arguments.size(); ++p)
        if (const auto type = types.ofExpression(arguments[p].first, arguments[p].second))
            unify(templ.parameterTypes[p], *type, templ, deduced);
    std::vector<std::string> values;
    for (const auto& parameter : templ.parameters) {
        const auto found = deduced.find(parameter.name);
        if (found == deduced.end())
            refuse(tokens[open - 1], "the template arguments of '" + tokens[open - 1].text + "' cannot be deduced by the kit "
                                     "from this call (it deduces them from variables, literals, constructors and casts): "
                                     "write them, as in " + tokens[open - 1].text + "<float>(...)");
        values.push_back(found->second);
    }
    return values;
}

std::string instanceText(const std::vector<Token>& tokens, const Template& templ, const std::vector<std::string>& arguments,
                         const std::string& name) {
    std::map<std::string, std::string> values;
    for (size_t p = 0; p < templ.parameters.size(); ++p) values[templ.parameters[p].name] = arguments[p];
    std::string text;
    for (size_t k = templ.declaration; k < templ.end; ++k) {
        const Token& token = tokens[k];
        std::string written = token.text;
        if (k == templ.name) written = name;
        else if (token.isIdentifier() && !followsMemberAccess(tokens, k) && values.contains(token.text)) written = values[token.text];
        text += (text.empty() ? "" : " ") + written;
    }
    return text;
}

struct Use {
    size_t begin = 0, end = 0; // the tokens replaced by the instance's name
    std::string instance;
};

// One round: every use of a template outside template definitions named by its instance, each
// new instance written before the top-level declaration of its first use.
std::vector<Token> instantiateOnce(const std::vector<Token>& tokens, std::set<std::string>& instantiated, bool& changed) {
    std::map<std::string, Template> templates;
    std::vector<std::pair<size_t, size_t>> definitions;
    for (size_t i = 0; i < tokens.size(); ++i)
        if (auto found = readTemplate(tokens, i)) {
            definitions.emplace_back(found->begin, found->end);
            templates[tokens[found->name].text] = *found;
            i = found->end - 1;
        }
    const auto inDefinition = [&](size_t i) {
        return std::any_of(definitions.begin(), definitions.end(), [&](const auto& d) { return i >= d.first && i < d.second; });
    };
    const DeclaredTypes types(tokens);
    const auto starts = topLevelStarts(tokens);
    std::vector<Use> uses;
    std::map<size_t, std::vector<std::string>> instancesBefore; // top-level start -> instance texts
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (!tokens[i].isIdentifier() || followsMemberAccess(tokens, i) || inDefinition(i)) continue;
        const auto found = templates.find(tokens[i].text);
        if (found == templates.end()) continue;
        const Template& templ = found->second;
        std::vector<std::string> arguments;
        size_t end = i + 1;
        if (i + 1 < tokens.size() && tokens[i + 1].is("<")) {
            const size_t close = closingAngle(tokens, i + 1);
            arguments = writtenArguments(tokens, i + 1, close);
            end = close + 1;
        } else if (!templ.isStruct && i + 1 < tokens.size() && tokens[i + 1].is("(")) {
            arguments = deducedArguments(tokens, templ, i + 1, types);
        } else {
            refuse(tokens[i], "the template '" + tokens[i].text + "' used without its arguments: write them, as in " +
                                  tokens[i].text + "<float>");
        }
        if (arguments.size() != templ.parameters.size())
            refuse(tokens[i], "the template '" + tokens[i].text + "' takes " + std::to_string(templ.parameters.size()) +
                                  " arguments; this use gives " + std::to_string(arguments.size()));
        const std::string name = mangled(tokens[i].text, arguments);
        uses.push_back({i, end, name});
        if (instantiated.insert(name).second) instancesBefore[starts[i]].push_back(instanceText(tokens, templ, arguments, name));
    }
    if (uses.empty() && instancesBefore.empty()) return tokens;
    changed = true;
    TokenWriter writer;
    size_t next = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (const auto before = instancesBefore.find(i); before != instancesBefore.end())
            for (const auto& text : before->second) writer.add(text, tokens[i].place, " ");
        if (next < uses.size() && uses[next].begin == i) {
            writer.replace(tokens[i], uses[next].instance);
            writer.drop(TokenSpan(tokens).subspan(i + 1, uses[next].end - i - 1));
            i = uses[next].end - 1;
            ++next;
            continue;
        }
        writer.keep(tokens[i]);
    }
    return writer.finish();
}

std::vector<Token> withoutTemplateDefinitions(const std::vector<Token>& tokens) {
    TokenWriter writer;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (const auto found = readTemplate(tokens, i)) {
            writer.drop(TokenSpan(tokens).subspan(found->begin, found->end - found->begin));
            i = found->end - 1;
            continue;
        }
        writer.keep(tokens[i]);
    }
    return writer.finish();
}

// ---- sizeof ------------------------------------------------------------------------------

struct Layout {
    size_t size = 0, alignment = 1;
};

class Sizes {
public:
    Sizes(const std::vector<Token>& tokens, bool sixteenBitTypes) : tokens_(tokens), sixteenBit_(sixteenBitTypes) {
        for (size_t i = 1; i + 1 < tokens.size(); ++i)
            if ((tokens[i - 1].is("struct") || tokens[i - 1].is("class")) && tokens[i].isIdentifier() && tokens[i + 1].is("{"))
                bodies_[tokens[i].text] = i + 1;
    }

    std::optional<Layout> of(const std::string& type, int depth = 0) const {
        if (const auto shape = builtinShape(type)) {
            const size_t scalar = scalarSize(shape->scalar);
            return Layout{scalar * size_t(shape->rows * shape->columns), scalar};
        }
        const auto body = bodies_.find(type);
        if (body == bodies_.end() || depth > 16) return std::nullopt;
        Layout layout;
        const size_t close = matchingClose(tokens_, body->second);
        for (size_t k = body->second + 1; k + 1 < close; ++k) {
            if (!tokens_[k + 1].isIdentifier() || (k > body->second + 1 && !tokens_[k - 1].is(";") && !tokens_[k - 1].is("{"))) continue;
            const auto member = of(tokens_[k].text, depth + 1);
            if (!member) continue;
            size_t count = 1;
            if (k + 4 < close && tokens_[k + 2].is("[") && tokens_[k + 3].kind == TokenKind::Number && tokens_[k + 4].is("]"))
                count = std::stoul(tokens_[k + 3].text);
            layout.size = (layout.size + member->alignment - 1) / member->alignment * member->alignment + member->size * count;
            layout.alignment = std::max(layout.alignment, member->alignment);
        }
        layout.size = (layout.size + layout.alignment - 1) / layout.alignment * layout.alignment;
        return layout;
    }

private:
    size_t scalarSize(const std::string& scalar) const {
        if (scalar == "double" || scalar == "int64_t" || scalar == "uint64_t" || scalar == "float64_t") return 8;
        const bool sixteen = scalar == "half" || scalar.rfind("min16", 0) == 0 || scalar == "min10float" || scalar == "min12int" ||
                             scalar == "float16_t" || scalar == "int16_t" || scalar == "uint16_t";
        return sixteen && sixteenBit_ ? 2 : 4;
    }

    const std::vector<Token>& tokens_;
    bool sixteenBit_;
    std::map<std::string, size_t> bodies_; // struct -> its "{"
};

std::vector<Token> lowerSizeof(const std::vector<Token>& tokens, bool sixteenBitTypes) {
    const Sizes sizes(tokens, sixteenBitTypes);
    const DeclaredTypes types(tokens);
    TokenWriter writer;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (!tokens[i].is("sizeof") || i + 3 >= tokens.size() || !tokens[i + 1].is("(")) {
            writer.keep(tokens[i]);
            continue;
        }
        const size_t close = matchingClose(tokens, i + 1);
        std::optional<std::string> type;
        if (close == i + 3 && types.isType(tokens[i + 2].text)) type = tokens[i + 2].text;
        if (const auto declared = close == i + 3 && !type ? types.ofName(tokens[i + 2].text, i) : std::nullopt; declared && declared->size() == 1)
            type = (*declared)[0];
        const auto layout = type ? sizes.of(*type) : std::nullopt;
        if (!layout)
            refuse(tokens[i], "sizeof of what the kit cannot lay out here: it takes a scalar, vector, matrix or struct type, "
                              "or a variable of one; write the size");
        writer.replace(tokens[i], std::to_string(layout->size) + "u");
        writer.drop(TokenSpan(tokens).subspan(i + 1, close - i));
        i = close;
    }
    return writer.finish();
}

} // namespace

std::vector<Token> lowerTemplates(const std::vector<Token>& tokens, bool sixteenBitTypes) {
    const bool anyTemplate = std::any_of(tokens.begin(), tokens.end(), [](const Token& t) { return t.is("template"); });
    std::vector<Token> current = tokens;
    if (anyTemplate) {
        std::set<std::string> instantiated;
        for (int round = 0; round < 32; ++round) {
            bool changed = false;
            current = instantiateOnce(current, instantiated, changed);
            if (!changed) break;
        }
        current = withoutTemplateDefinitions(current);
    }
    const bool anySizeof = std::any_of(current.begin(), current.end(), [](const Token& t) { return t.is("sizeof"); });
    return anySizeof ? lowerSizeof(current, sixteenBitTypes) : current;
}

} // namespace iblkit::lowering
