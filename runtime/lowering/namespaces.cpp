#include "namespaces.hpp"

#include "token_edit.hpp"

#include <map>
#include <memory>
#include <set>

namespace iblkit::lowering {
namespace {

struct Namespace {
    std::string prefix; // "" for the global one, "A__B__" for A::B
    Namespace* parent = nullptr;
    std::map<std::string, std::unique_ptr<Namespace>> children;
    std::set<std::string> names;

    Namespace* child(const std::string& name) {
        auto& slot = children[name];
        if (!slot) {
            slot = std::make_unique<Namespace>();
            slot->prefix = prefix + name + "__";
            slot->parent = this;
        }
        return slot.get();
    }
    const Namespace* find(const std::string& name) const {
        const auto found = children.find(name);
        return found == children.end() ? nullptr : found->second.get();
    }
};

// What a brace opened: a namespace body (its closing brace is dropped), a function body or
// other block (its declarations are local), a struct (members), a cbuffer (whose members
// belong to the enclosing namespace).
enum class Scope { Namespace, Block, Struct, CBuffer };

struct Frame {
    Scope scope;
    Namespace* space;             // the namespace the frame is in
    std::set<std::string> locals; // Block and Struct: names declared in it
    int parenDepth = 0;
    bool assigned = false;        // the statement so far holds a '=' at depth 0
    bool declaring = false;       // the statement so far declared a name
    bool expectsDeclarator = true;

    void startStatement() {
        assigned = declaring = false;
        expectsDeclarator = true;
    }
};

class NamespaceLowering {
public:
    explicit NamespaceLowering(TokenSpan tokens) : tokens_(tokens) { frames_.push_back({Scope::Namespace, &global_, {}}); }

    std::vector<Token> run() {
        for (size_t i = 0; i < tokens_.size(); ++i) i = step(i);
        return writer_.finish();
    }

private:
    Frame& frame() { return frames_.back(); }

    size_t step(size_t i) {
        const Token& token = tokens_[i];
        if (token.is("namespace") && !followsMemberAccess(tokens_, i)) return openNamespace(i);
        if (token.is("using") && !followsMemberAccess(tokens_, i)) return lowerUsing(i);
        if (token.is("struct") || token.is("class") || token.is("interface")) pendingScope_ = Scope::Struct;
        if (token.is("cbuffer") || token.is("tbuffer")) pendingScope_ = Scope::CBuffer;
        if (token.is("{")) return openBrace(i);
        if (token.is("}")) return closeBrace(i);
        trackStatement(token);
        if (token.isIdentifier() && !followsMemberAccess(tokens_, i)) return name(i);
        const bool globalName = token.is("::") && i + 1 < tokens_.size() && tokens_[i + 1].isIdentifier() &&
                                !(i > 0 && tokens_[i - 1].isIdentifier());
        if (globalName) return qualifiedName(i);
        writer_.keep(token);
        return i;
    }

    void trackStatement(const Token& token) {
        Frame& current = frame();
        if (token.is("(") || token.is("[")) ++current.parenDepth;
        if (token.is(")") || token.is("]")) --current.parenDepth;
        if (current.parenDepth != 0) return;
        if (token.is(";")) {
            current.startStatement();
            parameters_.clear();
            pendingScope_ = Scope::Block;
        }
        if (token.is("=")) current.assigned = true;
        if (token.is(",") && current.declaring) {
            current.assigned = false;
            current.expectsDeclarator = true;
        }
    }

    // "namespace A::B {": dropped, with its closing brace later.
    size_t openNamespace(size_t at) {
        if (frame().scope != Scope::Namespace) refuse(tokens_[at], "a namespace inside a function or struct");
        Namespace* space = frame().space;
        size_t i = at + 1;
        while (i < tokens_.size() && tokens_[i].isIdentifier()) {
            space = space->child(tokens_[i].text);
            if (!tokens_[++i].is("::")) break;
            ++i;
        }
        if (i < tokens_.size() && tokens_[i].is("="))
            refuse(tokens_[at], "a namespace alias cannot be lowered: write the namespace's own name");
        if (i >= tokens_.size() || !tokens_[i].is("{")) refuse(tokens_[at], "'namespace' is not followed by a name and '{'");
        writer_.drop(tokens_.subspan(at, i + 1 - at));
        frames_.push_back({Scope::Namespace, space, {}});
        namespaceDepths_.push_back(frames_.size());
        return i;
    }

    size_t lowerUsing(size_t at) {
        if (at + 1 < tokens_.size() && tokens_[at + 1].is("namespace"))
            refuse(tokens_[at], "'using namespace' cannot be lowered: qualify the names (N::name)");
        if (at + 2 >= tokens_.size() || !tokens_[at + 1].isIdentifier() || !tokens_[at + 2].is("="))
            refuse(tokens_[at], "'using' other than 'using Name = type;' cannot be lowered");
        // using Name = type;  ->  typedef type Name;
        const Token& alias = tokens_[at + 1];
        size_t end = at + 3;
        while (end < tokens_.size() && !tokens_[end].is(";")) ++end;
        if (end == tokens_.size()) refuse(tokens_[at], "'using' does not end in ';'");
        writer_.replace(tokens_[at], "typedef");
        writer_.drop(tokens_.subspan(at + 1, 2));
        for (size_t i = at + 3; i < end; ++i) i = step(i);
        declare(alias);
        const bool member = frame().scope == Scope::Namespace || frame().scope == Scope::CBuffer;
        writer_.add(member ? mangled(frame().space, alias.text) : alias.text, alias.place);
        return end - 1; // the ';' is the next step
    }

    size_t openBrace(size_t i) {
        Frame& outer = frame();
        Frame inner{pendingScope_, outer.space, {}};
        if (pendingScope_ == Scope::Block) inner.locals = std::move(parameters_);
        parameters_.clear();
        pendingScope_ = Scope::Block;
        frames_.push_back(std::move(inner));
        writer_.keep(tokens_[i]);
        return i;
    }

    size_t closeBrace(size_t i) {
        if (frames_.size() == 1) refuse(tokens_[i], "'}' closes nothing");
        const bool namespaceEnds = !namespaceDepths_.empty() && namespaceDepths_.back() == frames_.size();
        frames_.pop_back();
        if (namespaceEnds) {
            namespaceDepths_.pop_back();
            writer_.drop(tokens_[i]);
        } else {
            writer_.keep(tokens_[i]);
        }
        // After a function body or a namespace the next statement starts; after a struct or
        // cbuffer body its declarators or ';' follow.
        if (frame().scope == Scope::Namespace || frame().scope == Scope::Block) frame().startStatement();
        return i;
    }

    // An unqualified name: a declaration here, or a use resolved innermost scope first.
    size_t name(size_t i) {
        const Token& token = tokens_[i];
        if (i + 1 < tokens_.size() && tokens_[i + 1].is("::")) return qualifiedName(i);
        const Declaration declaration = declarationAt(i);
        if (declaration == Declaration::Parameter) {
            parameters_.insert(token.text);
        } else if (declaration == Declaration::Name) {
            declare(token);
            if (frame().scope == Scope::Namespace || frame().scope == Scope::CBuffer) {
                writer_.add(mangled(frame().space, token.text), token.place, token.leading);
                return i;
            }
        } else if (const Namespace* owner = ownerOf(token.text)) {
            writer_.add(mangled(owner, token.text), token.place, token.leading);
            return i;
        }
        writer_.keep(token);
        return i;
    }

    enum class Declaration { None, Name, Parameter };

    Declaration declarationAt(size_t i) {
        const Token& before = tokens_[i - (i > 0 ? 1 : 0)];
        const Token& next = tokens_[i + 1];
        const Frame& current = frame();
        if (before.is("struct") || before.is("class") || before.is("interface") || before.is("cbuffer") || before.is("tbuffer"))
            return Declaration::Name;
        const bool nextDeclarator = before.is(",") && current.declaring && current.expectsDeclarator && current.parenDepth == 0;
        if (i == 0 || !(isTypeLike(before) || nextDeclarator)) return Declaration::None;
        if (current.parenDepth > 0) { // a parameter of a function being declared, or a for loop's variable
            const bool parameter = next.is(",") || next.is(")") || next.is(":") || next.is("=") || next.is("[");
            return parameter ? Declaration::Parameter : Declaration::None;
        }
        if (current.assigned || !current.expectsDeclarator) return Declaration::None;
        const bool function = next.is("(") && current.scope != Scope::Block;
        const bool variable = next.is("=") || next.is(";") || next.is(",") || next.is("[") || next.is(":");
        if (function) parameters_.clear();
        if (!function && !variable) return Declaration::None;
        frames_.back().expectsDeclarator = false;
        frames_.back().declaring = true;
        return Declaration::Name;
    }

    void declare(const Token& token) {
        Frame& current = frame();
        if (current.scope == Scope::Block || current.scope == Scope::Struct) current.locals.insert(token.text);
        else current.space->names.insert(token.text);
    }

    // The namespace whose member `name` is, innermost scope first; nullptr for a local or a global.
    const Namespace* ownerOf(const std::string& name) const {
        for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
            if (frame->locals.contains(name)) return nullptr;
            if (frame->scope != Scope::Namespace) continue;
            for (const Namespace* space = frame->space; space != &global_; space = space->parent)
                if (space->names.contains(name)) return space;
            return nullptr;
        }
        return nullptr;
    }

    // "A::B::name" or "::name": one name, resolved from the innermost namespace outwards.
    size_t qualifiedName(size_t at) {
        std::vector<size_t> parts;
        size_t i = at;
        const bool global = tokens_[at].is("::");
        if (global) ++i;
        for (;;) {
            parts.push_back(i);
            if (i + 2 < tokens_.size() && tokens_[i + 1].is("::") && tokens_[i + 2].isIdentifier()) i += 2;
            else break;
        }
        const Namespace* space = resolvePath(parts, global);
        if (!space) { // not a namespace path (a struct's static member, say): left to glslang
            writer_.keep(tokens_.subspan(at, i + 1 - at));
            return i;
        }
        const Token& last = tokens_[parts.back()];
        writer_.drop(tokens_.subspan(at, i - at));
        writer_.add(mangled(space, last.text), last.place, tokens_[at].leading.empty() ? "" : " ");
        return i;
    }

    const Namespace* resolvePath(const std::vector<size_t>& parts, bool global) const {
        for (const Namespace* start = global ? &global_ : frame_space(); start; start = start->parent) {
            const Namespace* space = start;
            for (size_t n = 0; space && n + 1 < parts.size(); ++n) space = space->find(tokens_[parts[n]].text);
            if (space && (space != start || parts.size() == 1)) return space;
            if (global) break;
        }
        return nullptr;
    }

    const Namespace* frame_space() const { return frames_.back().space; }

    static std::string mangled(const Namespace* space, const std::string& name) { return space->prefix + name; }

    TokenSpan tokens_;
    TokenWriter writer_;
    Namespace global_;
    std::vector<Frame> frames_;
    std::vector<size_t> namespaceDepths_; // frames_.size() just after each namespace opened
    std::set<std::string> parameters_;    // of the function whose body opens next
    Scope pendingScope_ = Scope::Block;
};

} // namespace

std::vector<Token> lowerNamespaces(const std::vector<Token>& tokens) { return NamespaceLowering(tokens).run(); }

} // namespace iblkit::lowering
