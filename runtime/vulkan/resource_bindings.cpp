#include "resource_bindings.hpp"

#include "block_writer.hpp"
#include "vulkan_error.hpp"

namespace iblkit::vulkan {
namespace {

using compiler::ResourceKind;

vk::DescriptorType descriptorTypeOf(const compiler::ReflectedResource& resource) {
    switch (resource.kind) {
    case ResourceKind::ConstantBuffer: return vk::DescriptorType::eUniformBuffer;
    case ResourceKind::StorageBuffer: return vk::DescriptorType::eStorageBuffer;
    case ResourceKind::Texture: return vk::DescriptorType::eSampledImage;
    case ResourceKind::Sampler: return vk::DescriptorType::eSampler;
    case ResourceKind::StorageImage: return vk::DescriptorType::eStorageImage;
    case ResourceKind::TexelBuffer: return vk::DescriptorType::eUniformTexelBuffer;
    case ResourceKind::StorageTexelBuffer: return vk::DescriptorType::eStorageTexelBuffer;
    }
    return vk::DescriptorType::eStorageBuffer;
}

vk::ImageViewType viewTypeFor(const std::string& dimension) {
    if (dimension == "cube") return vk::ImageViewType::eCube;
    if (dimension == "2d_array") return vk::ImageViewType::e2DArray;
    return vk::ImageViewType::e2D;
}

} // namespace

ResourceBindings::ResourceBindings(const VulkanContext& context, compiler::ShaderReflection reflection,
                                   vk::ShaderStageFlags stages)
    : reflection_(std::move(reflection)), stages_(stages), device_(&context.device()) {
    std::map<uint32_t, std::vector<vk::DescriptorSetLayoutBinding>> bindings;
    std::map<vk::DescriptorType, uint32_t> counts;
    for (const auto& resource : reflection_.resources) {
        // An array of resources is one binding of `count` descriptors.
        bindings[resource.location.set].emplace_back(resource.location.binding, descriptorTypeOf(resource),
                                                     resource.location.count, stages_);
        counts[descriptorTypeOf(resource)] += resource.location.count;
    }
    std::vector<vk::DescriptorSetLayout> layouts;
    const uint32_t setCount = bindings.empty() ? 0 : bindings.rbegin()->first + 1;
    for (uint32_t set = 0; set < setCount; ++set) {
        setLayouts_.emplace(set, vk::raii::DescriptorSetLayout(context.device(), vk::DescriptorSetLayoutCreateInfo({}, bindings[set])));
        layouts.push_back(*setLayouts_.at(set));
    }
    std::vector<vk::PushConstantRange> pushRanges;
    if (reflection_.pushConstantSize > 0)
        pushRanges.emplace_back(stages_, 0, reflection_.pushConstantSize);
    pipelineLayout_ = vk::raii::PipelineLayout(context.device(), vk::PipelineLayoutCreateInfo({}, layouts, pushRanges));

    if (setCount > 0) {
        std::vector<vk::DescriptorPoolSize> sizes;
        for (const auto& [type, count] : counts) sizes.emplace_back(type, count);
        descriptorPool_ = vk::raii::DescriptorPool(
            context.device(), vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, setCount, sizes));
        vk::raii::DescriptorSets sets(context.device(), vk::DescriptorSetAllocateInfo(*descriptorPool_, layouts));
        for (uint32_t set = 0; set < setCount; ++set) sets_.emplace(set, std::move(sets[set]));
    }
}

const compiler::ReflectedResource& ResourceBindings::resource(const std::string& name) const {
    if (const auto* found = reflection_.find(name)) return *found;
    std::string names;
    for (const auto& resource : reflection_.resources) names += (names.empty() ? "" : ", ") + resource.name;
    throw VulkanError("the shader has no resource '" + name + "' (it has: " + names + ")");
}

void ResourceBindings::store(const std::string& name, uint32_t element, Bound bound) {
    const auto count = resource(name).location.count;
    if (element >= count)
        throw VulkanError("'" + name + "' has " + std::to_string(count) + " element" + (count == 1 ? "" : "s") +
                          ", not an element " + std::to_string(element));
    auto& elements = bound_[name];
    elements.resize(count);
    elements[element] = bound;
}

void ResourceBindings::bind(const std::string& name, const Buffer& buffer, uint32_t element) {
    const auto& target = resource(name);
    if (target.kind != ResourceKind::ConstantBuffer && target.kind != ResourceKind::StorageBuffer)
        throw VulkanError("'" + name + "' is a " + std::string(compiler::resourceKindName(target.kind)) + ", not a buffer");
    if (buffer.size() < target.blockSize)
        throw VulkanError("buffer '" + name + "' has " + std::to_string(buffer.size()) + " bytes; the shader reads " +
                          std::to_string(target.blockSize));
    store(name, element, {descriptorTypeOf(target), vk::DescriptorBufferInfo(buffer.handle(), 0, VK_WHOLE_SIZE), {}});
}

void ResourceBindings::bind(const std::string& name, Image& image, uint32_t mip, uint32_t element) {
    const auto& target = resource(name);
    const auto& desc = image.desc();
    const auto fail = [&](const std::string& why) { throw VulkanError("'" + name + "': " + why); };
    if (target.kind != ResourceKind::Texture && target.kind != ResourceKind::StorageImage)
        fail("the shader declares a " + std::string(compiler::resourceKindName(target.kind)) + ", not an image");
    if (target.dimension == "cube" && !desc.cube) fail("the shader samples a cube; the image is not one");
    if (target.dimension == "2d" && desc.layers != 1) fail("the shader declares a 2D image; the image has layers");
    if (target.dimension != "cube" && target.dimension != "2d" && target.dimension != "2d_array")
        fail("images of dimension " + target.dimension + " are not supported by the runtime yet");
    if (mip >= desc.mips) fail("mip " + std::to_string(mip) + " of an image with " + std::to_string(desc.mips));
    if (target.kind == ResourceKind::StorageImage) {
        if (!desc.storage) fail("the shader writes it as a storage image; the image was not made for storage");
        if (!target.vulkanFormat.empty() && target.vulkanFormat != desc.format->name)
            fail("wrong format: the shader declares " + target.vulkanFormat + ", the image is " +
                 std::string(desc.format->name));
        const auto type = target.dimension == "2d" ? vk::ImageViewType::e2D : vk::ImageViewType::e2DArray;
        store(name, element,
               {vk::DescriptorType::eStorageImage, {},
                vk::DescriptorImageInfo({}, image.view(type, mip, 1, 0, desc.layers), vk::ImageLayout::eGeneral)});
    } else {
        store(name, element,
               {vk::DescriptorType::eSampledImage, {},
                vk::DescriptorImageInfo({}, image.view(viewTypeFor(target.dimension), 0, desc.mips, 0, desc.layers),
                                        vk::ImageLayout::eGeneral)});
    }
}

void ResourceBindings::bind(const std::string& name, const Sampler& sampler, uint32_t element) {
    const auto& target = resource(name);
    if (target.kind != ResourceKind::Sampler)
        throw VulkanError("'" + name + "' is a " + std::string(compiler::resourceKindName(target.kind)) + ", not a sampler");
    store(name, element, {vk::DescriptorType::eSampler, {}, vk::DescriptorImageInfo(sampler.handle(), {}, {})});
}

void ResourceBindings::setPushConstants(std::span<const std::byte> bytes) {
    if (bytes.size() != reflection_.pushConstantSize)
        throw VulkanError("the shader's push constants are " + std::to_string(reflection_.pushConstantSize) +
                          " bytes, not " + std::to_string(bytes.size()));
    pushConstants_.assign(bytes.begin(), bytes.end());
}

void ResourceBindings::writeDescriptorSets() const {
    std::string missing;
    std::vector<vk::WriteDescriptorSet> writes;
    for (const auto& resource : reflection_.resources) {
        const auto found = bound_.find(resource.name);
        const bool array = resource.location.count > 1;
        for (uint32_t element = 0; element < resource.location.count; ++element) {
            if (found == bound_.end() || element >= found->second.size() || !found->second[element]) {
                missing += (missing.empty() ? "" : ", ") + resource.name + (array ? "[" + std::to_string(element) + "]" : "");
                continue;
            }
            const auto& bound = *found->second[element];
            const bool isBuffer = bound.type == vk::DescriptorType::eUniformBuffer || bound.type == vk::DescriptorType::eStorageBuffer;
            writes.push_back(vk::WriteDescriptorSet(*sets_.at(resource.location.set), resource.location.binding, element, 1,
                                                    bound.type, isBuffer ? nullptr : &bound.image,
                                                    isBuffer ? &bound.buffer : nullptr));
        }
    }
    if (!missing.empty()) throw VulkanError("the shader needs resources that are not bound: " + missing);
    if (reflection_.pushConstantSize > 0 && pushConstants_.empty())
        throw VulkanError("the shader's push constants are not set");
    device_->updateDescriptorSets(writes, {});
}

void ResourceBindings::record(const vk::raii::CommandBuffer& commands, vk::PipelineBindPoint bindPoint) const {
    std::vector<vk::DescriptorSet> sets;
    for (const auto& [index, set] : sets_) sets.push_back(*set);
    if (!sets.empty()) commands.bindDescriptorSets(bindPoint, *pipelineLayout_, 0, sets, {});
    if (!pushConstants_.empty()) commands.pushConstants<std::byte>(*pipelineLayout_, stages_, 0, pushConstants_);
}

std::vector<std::byte> specializationBytes(const compiler::ShaderReflection& reflection,
                                           const std::map<std::string, double>& values,
                                           std::vector<vk::SpecializationMapEntry>& entries) {
    std::vector<std::byte> bytes;
    for (const auto& [name, value] : values) {
        const auto constant = std::find_if(reflection.specializationConstants.begin(), reflection.specializationConstants.end(),
                                           [&wanted = name](const auto& c) { return c.name == wanted; });
        if (constant == reflection.specializationConstants.end())
            throw VulkanError("the shader has no specialization constant '" + name + "'");
        std::byte word[4];
        writeScalar(constant->type == "float" || constant->type == "int" ? constant->type : "uint", value, word,
                    "specialization constant '" + name + "'");
        entries.emplace_back(constant->constantId, static_cast<uint32_t>(bytes.size()), 4);
        bytes.insert(bytes.end(), word, word + 4);
    }
    return bytes;
}


} // namespace iblkit::vulkan
