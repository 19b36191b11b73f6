#pragma once

#include "bake_progress.hpp"
#include "bake_shaders.hpp"
#include "buffer.hpp"
#include "compute_program.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace iblkit::bake {

// One bake shader on the device: its program, the uniform buffer of its single cbuffer (set
// by member name before each dispatch) and the device time of its dispatches, reported to the
// current progress step.
class BakeKernel {
public:
    BakeKernel(const vulkan::VulkanContext& context, const BakeShader& shader);

    vulkan::ComputeProgram& program() { return program_; }
    void setParameters(const std::map<std::string, std::vector<double>>& values);
    void run(std::array<uint32_t, 3> threads, BakeProgress& progress);
    void runGroups(std::array<uint32_t, 3> groups, BakeProgress& progress);

private:
    const vulkan::VulkanContext& context_;
    vulkan::ComputeProgram program_;
    std::unique_ptr<vulkan::Buffer> parameters_;
};

} // namespace iblkit::bake
