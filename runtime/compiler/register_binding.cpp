#include "register_binding.hpp"

#include "compile_error.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <set>

namespace iblkit::compiler {

char registerLetter(RegisterClass registerClass) {
    constexpr char letters[] = {'b', 't', 's', 'u'};
    return letters[static_cast<size_t>(registerClass)];
}

std::optional<RegisterClass> registerClassFromLetter(char letter) {
    for (RegisterClass registerClass : kRegisterClasses)
        if (registerLetter(registerClass) == letter) return registerClass;
    return std::nullopt;
}

uint32_t BindingShifts::capacity(RegisterClass registerClass) const {
    const uint32_t base = of(registerClass);
    if (base > kLargestBinding) return 0;
    uint32_t next = kLargestBinding + 1;
    for (uint32_t other : shift)
        if (other > base && other < next) next = other;
    return next - base;
}

std::string ResourceRegister::registerName() const {
    if (vulkanBinding) return "vk::binding";
    return std::string(1, registerLetter(registerClass)) + std::to_string(registerIndex);
}

namespace {

using ClassAndSpace = std::pair<RegisterClass, uint32_t>;

ResourceRegister bindResource(const DeclaredResource& resource, uint32_t registerIndex, const BindingShifts& shifts,
                              const std::string& sourceName) {
    const uint64_t capacity = shifts.capacity(resource.registerClass);
    const char letter = registerLetter(resource.registerClass);
    if (uint64_t(registerIndex) + resource.count > capacity) {
        const bool highest = uint64_t(shifts.of(resource.registerClass)) + capacity == uint64_t(kLargestBinding) + 1;
        throw CompileError(sourceName + ": error: '" + resource.name + "' is in register " + letter +
                           std::to_string(registerIndex) + ", but the " + letter + " class holds only " +
                           std::to_string(capacity) + " registers under the binding shifts; " +
                           (highest ? "bindings end at " + std::to_string(kLargestBinding) + " (glslang's largest)"
                                    : std::string("raise the next class's --binding-shift")));
    }
    return ResourceRegister{resource.name,
                            resource.registerClass,
                            registerIndex,
                            resource.count,
                            resource.space,
                            resource.explicitRegister.has_value(),
                            resource.space,
                            shifts.of(resource.registerClass) + registerIndex};
}

ResourceRegister bindExplicitly(const DeclaredResource& resource) {
    const auto& vulkan = *resource.vulkanBinding;
    if (vulkan.binding > kLargestBinding)
        throw CompileError(vulkan.place + ": error: [[vk::binding(" + std::to_string(vulkan.binding) + ")]] on '" +
                           resource.name + "': bindings end at " + std::to_string(kLargestBinding) + " (glslang's largest)");
    return ResourceRegister{resource.name, resource.registerClass, 0, resource.count, resource.space, false,
                            vulkan.set, vulkan.binding, true};
}

std::string describeBinding(const ResourceRegister& resource) {
    return resource.vulkanBinding ? "[[vk::binding]]" : "register " + resource.registerName() + ", space" + std::to_string(resource.space);
}

// No two resources on one set and binding. In Vulkan an array of resources is one binding whose
// descriptor count is the array's size, so it takes no binding but its own (its registers are
// another matter: an array of N takes N, and the register rule keeps those apart).
void requireDistinctBindings(const std::vector<ResourceRegister>& assigned, const std::string& sourceName) {
    std::map<std::pair<uint32_t, uint32_t>, const ResourceRegister*> taken;
    for (const auto& resource : assigned) {
        const auto [it, inserted] = taken.emplace(std::make_pair(resource.set, resource.binding), &resource);
        // A texture and a sampler that [[vk::binding]] puts on one binding are a combined image
        // sampler's two halves, as DXC writes them and Vulkan reads them.
        const bool combined = !inserted && resource.vulkanBinding && it->second->vulkanBinding &&
                              std::set{resource.registerClass, it->second->registerClass} ==
                                  std::set{RegisterClass::ShaderResource, RegisterClass::Sampler};
        if (!inserted && !combined)
            throw CompileError(sourceName + ": error: '" + it->second->name + "' (" + describeBinding(*it->second) +
                               ") and '" + resource.name + "' (" + describeBinding(resource) + ") are both on set " +
                               std::to_string(resource.set) + ", binding " + std::to_string(resource.binding));
    }
}

} // namespace

namespace {

constexpr uint32_t kDefaultRange = 32;

// The registers each class needs: past its highest explicit register, and one each for the rest.
std::array<uint64_t, 4> registersNeeded(const std::vector<DeclaredResource>& declared) {
    std::array<uint64_t, 4> explicitEnd{}, implicitCount{};
    for (const auto& resource : declared) {
        if (resource.vulkanBinding) continue;
        const auto index = size_t(resource.registerClass);
        if (resource.explicitRegister) explicitEnd[index] = std::max<uint64_t>(explicitEnd[index], *resource.explicitRegister + uint64_t(resource.count));
        else implicitCount[index] += resource.count;
    }
    std::array<uint64_t, 4> needed{};
    for (size_t i = 0; i < 4; ++i) needed[i] = explicitEnd[i] + implicitCount[i];
    return needed;
}

} // namespace

BindingShifts grownToFit(const std::vector<DeclaredResource>& declared, const BindingShifts& shifts) {
    if (shifts.shift != BindingShifts{}.shift) return shifts; // the user's own: never moved
    const auto needed = registersNeeded(declared);
    BindingShifts grown;
    uint64_t next = 0;
    for (const RegisterClass registerClass : kRegisterClasses) {
        grown.set(registerClass, uint32_t(std::min<uint64_t>(next, kLargestBinding)));
        const uint64_t range = std::max<uint64_t>(kDefaultRange, (needed[size_t(registerClass)] + kDefaultRange - 1) / kDefaultRange * kDefaultRange);
        next += range;
    }
    return grown;
}

std::vector<ResourceRegister> assignRegisters(const std::vector<DeclaredResource>& declared,
                                              const BindingShifts& shifts, const std::string& sourceName) {
    for (RegisterClass a : kRegisterClasses)
        for (RegisterClass b : kRegisterClasses)
            if (a < b && shifts.of(a) == shifts.of(b))
                throw CompileError(sourceName + ": error: the binding shifts of " + registerLetter(a) + " and " +
                                   registerLetter(b) + " are both " + std::to_string(shifts.of(a)) +
                                   "; each class needs a range of its own");
    std::map<ClassAndSpace, std::map<uint32_t, std::string>> taken;
    for (const auto& resource : declared) {
        if (!resource.explicitRegister || resource.vulkanBinding) continue;
        auto& users = taken[{resource.registerClass, resource.space}];
        for (uint32_t index = *resource.explicitRegister; index < *resource.explicitRegister + resource.count; ++index) {
            auto [it, inserted] = users.emplace(index, resource.name);
            if (!inserted)
                throw CompileError(sourceName + ": error: register " + registerLetter(resource.registerClass) +
                                   std::to_string(index) + ", space" + std::to_string(resource.space) +
                                   " is used by both '" + it->second + "' and '" + resource.name + "'");
        }
    }

    std::vector<ResourceRegister> assigned;
    assigned.reserve(declared.size());
    for (const auto& resource : declared) {
        if (resource.vulkanBinding) {
            assigned.push_back(bindExplicitly(resource));
            continue;
        }
        uint32_t registerIndex = 0;
        if (resource.explicitRegister) {
            registerIndex = *resource.explicitRegister;
        } else {
            auto& users = taken[{resource.registerClass, resource.space}];
            const auto rangeIsFree = [&](uint32_t first) {
                for (uint32_t index = first; index < first + resource.count; ++index)
                    if (users.count(index)) return false;
                return true;
            };
            while (!rangeIsFree(registerIndex)) ++registerIndex;
            for (uint32_t index = registerIndex; index < registerIndex + resource.count; ++index)
                users.emplace(index, resource.name);
        }
        assigned.push_back(bindResource(resource, registerIndex, shifts, sourceName));
    }
    requireDistinctBindings(assigned, sourceName);
    return assigned;
}

void parseBindingShift(std::string_view text, BindingShifts& shifts) {
    const auto fail = [&] {
        throw CompileError("error: --binding-shift expects CLASS=N with CLASS one of b, t, s, u, got '" +
                           std::string(text) + "'");
    };
    if (text.size() < 3 || text[1] != '=') fail();
    const auto registerClass = registerClassFromLetter(text[0]);
    if (!registerClass) fail();
    uint32_t value = 0;
    const auto digits = text.substr(2);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size()) fail();
    if (value > kLargestBinding)
        throw CompileError("error: --binding-shift " + std::string(text) + ": bindings end at " +
                           std::to_string(kLargestBinding) + " (glslang holds them in 16 bits)");
    shifts.set(*registerClass, value);
}

} // namespace iblkit::compiler
