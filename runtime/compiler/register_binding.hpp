#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::compiler {

// The four HLSL register classes: b (constant buffers), t (shader resource views),
// s (samplers), u (unordered access views).
enum class RegisterClass { ConstantBuffer, ShaderResource, Sampler, UnorderedAccess };
inline constexpr std::array kRegisterClasses{RegisterClass::ConstantBuffer, RegisterClass::ShaderResource,
                                             RegisterClass::Sampler, RegisterClass::UnorderedAccess};

char registerLetter(RegisterClass registerClass);
std::optional<RegisterClass> registerClassFromLetter(char letter);

// The one rule from HLSL registers to Vulkan descriptors (docs/bindings.md):
//   set = space,  binding = shift[class] + register.
// Each class owns the bindings from its shift up to the next larger shift, so no two
// resources can share a binding; a register that would cross into the next class's range
// is an error, not a silent clash.
// glslang holds a binding in 16 bits, 0xFFFF meaning none: 65534 is the largest binding.
inline constexpr uint32_t kLargestBinding = 65534;

struct BindingShifts {
    std::array<uint32_t, 4> shift{0, 32, 64, 96}; // b, t, s, u

    uint32_t of(RegisterClass registerClass) const { return shift[static_cast<size_t>(registerClass)]; }
    void set(RegisterClass registerClass, uint32_t value) { shift[static_cast<size_t>(registerClass)] = value; }
    // Registers of the class that fit below the next class's shift, or for the highest class
    // up to kLargestBinding.
    uint32_t capacity(RegisterClass registerClass) const;
};

// A set and binding written in the source with [[vk::binding(binding, set)]]: it wins over the
// register rule, as in DXC.
struct ExplicitBinding {
    uint32_t set = 0;
    uint32_t binding = 0;
    std::string place; // "file:line:col" of the attribute, for messages
};

// A resource as declared in HLSL, in declaration order.
struct DeclaredResource {
    std::string name;
    RegisterClass registerClass;
    std::optional<uint32_t> explicitRegister; // from ": register(x#)"
    uint32_t space = 0;
    uint32_t count = 1; // registers taken: the array size of an array of resources
    std::optional<ExplicitBinding> vulkanBinding = std::nullopt;
};

struct ResourceRegister {
    std::string name;
    RegisterClass registerClass;
    uint32_t registerIndex;
    uint32_t count;
    uint32_t space;
    bool explicitRegister;
    uint32_t set;
    uint32_t binding;
    bool vulkanBinding = false; // set and binding from [[vk::binding]]; no register

    std::string registerName() const; // "t0", "u3", or "vk::binding" for one without a register
};

// Gives each resource without a register the lowest free register of its class and space,
// in declaration order (as FXC and DXC do), then applies the binding rule; a resource with
// [[vk::binding]] takes its own set and binding and no register.
// Throws CompileError on a register used twice, one outside its class's range, or a set and
// binding that two resources would share.
// The default shifts (0, 32, 64, 96) grown in steps of 32 so that every class holds the registers
// its resources need (a t9 array of 40 textures moves s and u up); shifts a user gave are kept.
BindingShifts grownToFit(const std::vector<DeclaredResource>& declared, const BindingShifts& shifts);

std::vector<ResourceRegister> assignRegisters(const std::vector<DeclaredResource>& declared,
                                              const BindingShifts& shifts, const std::string& sourceName);

// Parses "b=0" / "t=32" as given to --binding-shift.
void parseBindingShift(std::string_view text, BindingShifts& shifts);

} // namespace iblkit::compiler
