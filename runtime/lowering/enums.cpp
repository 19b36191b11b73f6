#include "enums.hpp"

#include "token_edit.hpp"

#include <map>
#include <set>

namespace iblkit::lowering {
namespace {

struct EnumType {
    bool scoped = false;
    std::set<std::string> enumerators;
};

struct Enumerator {
    const Token* name = nullptr;
    size_t valueBegin = 0, valueEnd = 0; // the tokens after '=', empty when implicit
};

class EnumLowering {
public:
    explicit EnumLowering(TokenSpan tokens) : tokens_(tokens) {}

    std::vector<Token> run() {
        for (size_t i = 0; i < tokens_.size(); ++i) {
            if (tokens_[i].is("enum") && !followsMemberAccess(tokens_, i)) i = lowerEnum(i);
            else i = keepOrQualify(i, nullptr);
        }
        return writer_.finish();
    }

private:
    // Keeps tokens_[i], or writes "E::A" as the enumerator's name; returns the last index used.
    // Inside an enum's own values (`within`), a scoped enum's enumerators are named without "E::"; an
    // unscoped enum's are global names already.
    size_t keepOrQualify(size_t i, const std::pair<const std::string, EnumType>* within) {
        const Token& token = tokens_[i];
        const bool member = followsMemberAccess(tokens_, i);
        if (token.isIdentifier() && !member && i + 2 < tokens_.size() && tokens_[i + 1].is("::") && enums_.contains(token.text)) {
            const auto& [name, type] = *enums_.find(token.text);
            const Token& enumerator = tokens_[i + 2];
            if (!enumerator.isIdentifier() || !type.enumerators.contains(enumerator.text))
                refuse(enumerator, "'" + enumerator.text + "' is not an enumerator of enum '" + name + "'");
            writer_.add(type.scoped ? scopedEnumeratorName(name, enumerator.text) : enumerator.text, token.place, token.leading);
            writer_.drop(tokens_.subspan(i + 1, 2));
            return i + 2;
        }
        if (within && token.isIdentifier() && !member && within->second.enumerators.contains(token.text) &&
            !followsQualifier(tokens_, i)) {
            const bool scoped = within->second.scoped;
            writer_.add(scoped ? scopedEnumeratorName(within->first, token.text) : token.text, token.place, token.leading);
            return i;
        }
        writer_.keep(token);
        return i;
    }

    // Returns the index of the enum's closing ';'.
    size_t lowerEnum(size_t at) {
        size_t i = at + 1;
        const bool scoped = tokens_[i].is("class") || tokens_[i].is("struct");
        if (scoped) ++i;
        std::string name;
        if (tokens_[i].isIdentifier()) name = tokens_[i++].text;
        if (scoped && name.empty()) refuse(tokens_[at], "a scoped enum needs a name");
        size_t typeBegin = i, typeEnd = i;
        if (tokens_[i].is(":")) {
            typeBegin = ++i;
            while (i < tokens_.size() && !tokens_[i].is("{") && !tokens_[i].is(";")) ++i;
            typeEnd = i;
            if (typeBegin == typeEnd) refuse(tokens_[at], "enum '" + name + "' names no underlying type after ':'");
        }
        const std::string underlying = typeBegin == typeEnd ? "int" : spelled(typeBegin, typeEnd);
        if (i >= tokens_.size() || (!tokens_[i].is("{") && !tokens_[i].is(";")))
            refuse(tokens_[at], "enum '" + name + "' is not followed by '{' or ';'");
        if (name.empty()) writer_.drop(tokens_[at]);
        else writer_.replace(tokens_[at], "typedef " + underlying + " " + name + ";");
        writer_.drop(tokens_.subspan(at + 1, i - at - 1));
        if (tokens_[i].is(";")) { // a declaration before the definition: the typedef is all it needs
            writer_.drop(tokens_[i]);
            return i;
        }
        const size_t close = matchingClose(tokens_, i);
        auto& type = enums_[name.empty() ? "" : name];
        type.scoped = scoped;
        writer_.drop(tokens_[i]);
        writeEnumerators(*enums_.find(name), name.empty() ? underlying : name, i + 1, close);
        writer_.drop(tokens_[close]);
        return writeDeclarators(tokens_[at], name.empty() ? underlying : name, close + 1);
    }

    void writeEnumerators(const std::pair<const std::string, EnumType>& type, const std::string& valueType, size_t begin,
                          size_t end) {
        std::string previous;
        for (const auto& [first, last] : splitAtCommas(tokens_, begin, end)) {
            if (first == last) { // a trailing comma
                if (first < end) writer_.drop(tokens_[first]);
                continue;
            }
            const Token& enumerator = tokens_[first];
            if (!enumerator.isIdentifier() || (first + 1 < last && !tokens_[first + 1].is("=")))
                refuse(enumerator, "'" + enumerator.text + "' is not an enumerator (NAME or NAME = VALUE)");
            const std::string own = type.second.scoped ? scopedEnumeratorName(type.first, enumerator.text) : enumerator.text;
            const bool valued = first + 1 < last;
            writer_.drop(tokens_.subspan(first, valued ? 2 : 1));
            writer_.add("static const " + valueType + " " + own + " =", enumerator.place);
            if (valued)
                for (size_t i = first + 2; i < last; ++i) i = keepOrQualify(i, &type);
            else
                writer_.add(previous.empty() ? "0" : previous + " + 1", enumerator.place);
            writer_.add(";", enumerator.place, "");
            enums_[type.first].enumerators.insert(enumerator.text);
            previous = own;
            if (last < end) writer_.drop(tokens_[last]); // the comma
        }
    }

    // "enum E { ... } a, b;" declares a and b of type E. Returns the index of the ';'.
    size_t writeDeclarators(const Token& at, const std::string& type, size_t begin) {
        size_t end = begin;
        while (end < tokens_.size() && !tokens_[end].is(";")) ++end;
        if (end == tokens_.size()) refuse(at, "the enum does not end in ';'");
        if (end > begin) {
            writer_.add(type, at.place);
            writer_.keep(tokens_.subspan(begin, end - begin));
            writer_.keep(tokens_[end]);
        } else {
            writer_.drop(tokens_[end]);
        }
        return end;
    }

    std::string spelled(size_t begin, size_t end) const {
        std::string text;
        for (size_t i = begin; i < end; ++i) text += (i > begin ? " " : "") + tokens_[i].text;
        return text;
    }

    TokenSpan tokens_;
    TokenWriter writer_;
    std::map<std::string, EnumType> enums_;
};

} // namespace

std::string scopedEnumeratorName(const std::string& enumName, const std::string& enumerator) {
    return enumName + "__" + enumerator;
}

std::vector<Token> lowerEnums(const std::vector<Token>& tokens) { return EnumLowering(tokens).run(); }

} // namespace iblkit::lowering
