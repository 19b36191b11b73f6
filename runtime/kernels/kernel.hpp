#pragma once

#include "kernels/kernel_parameters.hpp"
#include "kernels/kernel_table.hpp"

#include "buffer.hpp"
#include "compute_program.hpp"

#include <array>
#include <memory>

namespace iblkit::kernels {

// Device and wall time summed over dispatches.
struct DispatchTotals {
    double deviceMilliseconds = 0;
    double wallMilliseconds = 0;
    uint32_t dispatches = 0;

    DispatchTotals& operator+=(const DispatchTotals& more) {
        deviceMilliseconds += more.deviceMilliseconds;
        wallMilliseconds += more.wallMilliseconds;
        dispatches += more.dispatches;
        return *this;
    }
};

// One kernel on a Vulkan device: its program, the uniform buffer of its single cbuffer (set
// from the role's parameter struct before each dispatch) and the time its dispatches took.
class Kernel {
public:
    Kernel(const vulkan::VulkanContext& context, const KernelProgram& program);

    vulkan::ComputeProgram& program() { return program_; }
    const vulkan::VulkanContext& context() const { return context_; }
    // Sets the cbuffer's members by name. A member SPIRV-Cross renamed in a round trip
    // ("_21_Roughness") takes the value of its original name.
    void setParameters(const NamedValues& values);
    void run(std::array<uint32_t, 3> threads);
    void runGroups(std::array<uint32_t, 3> groups);

    const DispatchTotals& totals() const { return totals_; }
    // The totals so far, then zero.
    DispatchTotals takeTotals();

private:
    const vulkan::VulkanContext& context_;
    vulkan::ComputeProgram program_;
    std::unique_ptr<vulkan::Buffer> parameters_;
    DispatchTotals totals_;
};

} // namespace iblkit::kernels
