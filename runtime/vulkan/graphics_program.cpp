#include "graphics_program.hpp"

#include "timed_submission.hpp"
#include "vulkan_error.hpp"

#include <algorithm>

namespace iblkit::vulkan {
namespace {

constexpr vk::ImageLayout kGeneral = vk::ImageLayout::eGeneral;

// The colour attachment references by location: SV_Target2 alone still needs slots 0 and 1.
std::vector<vk::AttachmentReference> colorReferences(const GraphicsStateDesc& state) {
    uint32_t slots = 0;
    for (const auto& target : state.colorTargets) slots = std::max(slots, target.location + 1);
    std::vector<vk::AttachmentReference> references(slots, vk::AttachmentReference(VK_ATTACHMENT_UNUSED, kGeneral));
    for (uint32_t i = 0; i < state.colorTargets.size(); ++i) references[state.colorTargets[i].location].attachment = i;
    return references;
}

vk::raii::RenderPass makeRenderPass(const VulkanContext& context, const GraphicsStateDesc& state) {
    std::vector<vk::AttachmentDescription> attachments;
    for (const auto& target : state.colorTargets)
        attachments.emplace_back(vk::AttachmentDescriptionFlags(), target.format->format, vk::SampleCountFlagBits::e1,
                                 vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore, vk::AttachmentLoadOp::eDontCare,
                                 vk::AttachmentStoreOp::eDontCare, kGeneral, kGeneral);
    const vk::AttachmentReference depthReference(uint32_t(attachments.size()), kGeneral);
    if (state.depth)
        attachments.emplace_back(vk::AttachmentDescriptionFlags(), vk::Format::eD32Sfloat, vk::SampleCountFlagBits::e1,
                                 vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore, vk::AttachmentLoadOp::eDontCare,
                                 vk::AttachmentStoreOp::eDontCare, kGeneral, kGeneral);
    const auto colors = colorReferences(state);
    const vk::SubpassDescription subpass({}, vk::PipelineBindPoint::eGraphics, {}, colors, {},
                                         state.depth ? &depthReference : nullptr);
    const auto everything = vk::AccessFlagBits::eMemoryRead | vk::AccessFlagBits::eMemoryWrite;
    const std::array dependencies{
        vk::SubpassDependency(VK_SUBPASS_EXTERNAL, 0, vk::PipelineStageFlagBits::eAllCommands,
                              vk::PipelineStageFlagBits::eAllGraphics, everything, everything),
        vk::SubpassDependency(0, VK_SUBPASS_EXTERNAL, vk::PipelineStageFlagBits::eAllGraphics,
                              vk::PipelineStageFlagBits::eAllCommands, everything, everything)};
    return vk::raii::RenderPass(context.device(), vk::RenderPassCreateInfo({}, attachments, subpass, dependencies));
}

vk::PipelineColorBlendAttachmentState blendState(BlendMode mode) {
    using F = vk::BlendFactor;
    const auto all = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG | vk::ColorComponentFlagBits::eB |
                     vk::ColorComponentFlagBits::eA;
    const auto blend = [&](F source, F destination) {
        return vk::PipelineColorBlendAttachmentState(VK_TRUE, source, destination, vk::BlendOp::eAdd, source, destination,
                                                     vk::BlendOp::eAdd, all);
    };
    switch (mode) {
    case BlendMode::Alpha: return blend(F::eSrcAlpha, F::eOneMinusSrcAlpha);
    case BlendMode::Premultiplied: return blend(F::eOne, F::eOneMinusSrcAlpha);
    case BlendMode::Additive: return blend(F::eOne, F::eOne);
    case BlendMode::None: break;
    }
    vk::PipelineColorBlendAttachmentState none;
    none.colorWriteMask = all;
    return none;
}

// The constants of `all` that one stage declares: the others belong to the other stage.
std::map<std::string, double> constantsOf(const compiler::ShaderReflection& stage, const std::map<std::string, double>& all) {
    std::map<std::string, double> mine;
    for (const auto& [name, value] : all)
        for (const auto& constant : stage.specializationConstants)
            if (constant.name == name) mine[name] = value;
    return mine;
}

vk::ClearValue clearValueOf(const TexelFormat& format, const std::array<double, 4>& value) {
    if (format.kind == ComponentKind::UInt)
        return vk::ClearColorValue(std::array<uint32_t, 4>{uint32_t(value[0]), uint32_t(value[1]), uint32_t(value[2]), uint32_t(value[3])});
    if (format.kind == ComponentKind::SInt)
        return vk::ClearColorValue(std::array<int32_t, 4>{int32_t(value[0]), int32_t(value[1]), int32_t(value[2]), int32_t(value[3])});
    return vk::ClearColorValue(std::array<float, 4>{float(value[0]), float(value[1]), float(value[2]), float(value[3])});
}

} // namespace

compiler::ShaderReflection mergeStageReflections(const compiler::ShaderReflection& vertex, const compiler::ShaderReflection& pixel) {
    compiler::ShaderReflection merged = vertex;
    merged.entryPoint = vertex.entryPoint + "+" + pixel.entryPoint;
    for (const auto& resource : pixel.resources) {
        const auto* same = merged.find(resource.name);
        if (!same) {
            merged.resources.push_back(resource);
            continue;
        }
        if (same->location.set != resource.location.set || same->location.binding != resource.location.binding ||
            same->kind != resource.kind)
            throw VulkanError("'" + resource.name + "' is a different resource in the vertex and the pixel shader");
    }
    for (const auto& constant : pixel.specializationConstants)
        if (std::none_of(merged.specializationConstants.begin(), merged.specializationConstants.end(),
                         [&](const auto& c) { return c.name == constant.name; }))
            merged.specializationConstants.push_back(constant);
    if (merged.pushConstantSize == 0) {
        merged.pushConstantBlock = pixel.pushConstantBlock;
        merged.pushConstants = pixel.pushConstants;
    }
    merged.pushConstantSize = std::max(vertex.pushConstantSize, pixel.pushConstantSize);
    return merged;
}

GraphicsProgram::GraphicsProgram(const VulkanContext& context, const std::vector<uint32_t>& vertexSpirv,
                                 const compiler::ShaderReflection& vertexReflection, const std::vector<uint32_t>& pixelSpirv,
                                 const compiler::ShaderReflection& pixelReflection, const GraphicsStateDesc& state,
                                 const std::map<std::string, double>& specialization)
    : state_(state), bindings_(context, mergeStageReflections(vertexReflection, pixelReflection),
                               vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment) {
    if (!context.canDraw()) throw VulkanError(context.deviceInfo().name + " has no queue that draws");
    if (vertexReflection.stage != compiler::ShaderStage::Vertex)
        throw VulkanError("entry point '" + vertexReflection.entryPoint + "' is not a vertex shader");
    if (pixelReflection.stage != compiler::ShaderStage::Fragment)
        throw VulkanError("entry point '" + pixelReflection.entryPoint + "' is not a pixel shader");
    for (const auto& [name, value] : specialization)
        if (std::none_of(bindings_.reflection().specializationConstants.begin(), bindings_.reflection().specializationConstants.end(),
                         [&](const auto& c) { return c.name == name; }))
            throw VulkanError("neither shader has a specialization constant '" + name + "'");
    for (const auto* spirv : {&vertexSpirv, &pixelSpirv})
        if (const auto missing = missingShaderFeature(*spirv, context.shaderFeatures()); !missing.empty())
            throw VulkanError("the shader needs " + missing + ", which " + context.deviceInfo().name + " does not have");
    renderPass_ = makeRenderPass(context, state_);

    const vk::raii::ShaderModule vertexModule(context.device(), vk::ShaderModuleCreateInfo({}, vertexSpirv.size() * 4, vertexSpirv.data()));
    const vk::raii::ShaderModule pixelModule(context.device(), vk::ShaderModuleCreateInfo({}, pixelSpirv.size() * 4, pixelSpirv.data()));
    std::vector<vk::SpecializationMapEntry> vertexEntries, pixelEntries;
    const auto vertexData = specializationBytes(vertexReflection, constantsOf(vertexReflection, specialization), vertexEntries);
    const auto pixelData = specializationBytes(pixelReflection, constantsOf(pixelReflection, specialization), pixelEntries);
    const vk::SpecializationInfo vertexConstants(uint32_t(vertexEntries.size()), vertexEntries.data(), vertexData.size(), vertexData.data());
    const vk::SpecializationInfo pixelConstants(uint32_t(pixelEntries.size()), pixelEntries.data(), pixelData.size(), pixelData.data());
    const std::array stages{
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eVertex, *vertexModule, vertexReflection.entryPoint.c_str(),
                                          &vertexConstants),
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eFragment, *pixelModule, pixelReflection.entryPoint.c_str(),
                                          &pixelConstants)};

    std::vector<vk::VertexInputBindingDescription> vertexBindings;
    std::vector<vk::VertexInputAttributeDescription> vertexAttributes;
    for (uint32_t i = 0; i < state_.attributes.size(); ++i) {
        vertexBindings.emplace_back(i, state_.attributes[i].stride, vk::VertexInputRate::eVertex);
        vertexAttributes.emplace_back(state_.attributes[i].location, i, state_.attributes[i].format, 0);
    }
    const vk::PipelineVertexInputStateCreateInfo vertexInput({}, vertexBindings, vertexAttributes);
    const vk::PipelineInputAssemblyStateCreateInfo assembly({}, state_.topology, VK_FALSE);
    const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
    // Vulkan decides the winding in framebuffer coordinates, whose y runs down the target as
    // Direct3D's does: clockwise in the target is clockwise to it, flipped viewport or not.
    const vk::PipelineRasterizationStateCreateInfo raster(
        {}, VK_FALSE, VK_FALSE, vk::PolygonMode::eFill, state_.cull,
        state_.frontClockwise ? vk::FrontFace::eClockwise : vk::FrontFace::eCounterClockwise, VK_FALSE, 0, 0, 0, 1.0f);
    const vk::PipelineMultisampleStateCreateInfo multisample({}, vk::SampleCountFlagBits::e1);
    const vk::PipelineDepthStencilStateCreateInfo depth({}, state_.depth.has_value(), state_.depth && state_.depth->write,
                                                        state_.depth ? state_.depth->test : vk::CompareOp::eAlways);
    const auto references = colorReferences(state_);
    std::vector<vk::PipelineColorBlendAttachmentState> blends(references.size(), blendState(BlendMode::None));
    for (const auto& target : state_.colorTargets) blends[target.location] = blendState(target.blend);
    const vk::PipelineColorBlendStateCreateInfo blend({}, VK_FALSE, vk::LogicOp::eCopy, blends);
    const std::array dynamic{vk::DynamicState::eViewport, vk::DynamicState::eScissor};
    const vk::PipelineDynamicStateCreateInfo dynamicState({}, dynamic);
    try {
        pipeline_ = vk::raii::Pipeline(context.device(), context.pipelineCache(),
                                       vk::GraphicsPipelineCreateInfo({}, stages, &vertexInput, &assembly, nullptr, &viewport,
                                                                      &raster, &multisample, &depth, &blend, &dynamicState,
                                                                      *bindings_.pipelineLayout(), *renderPass_, 0));
    } catch (const vk::SystemError& error) {
        throw VulkanError("the driver could not build a graphics pipeline of '" + vertexReflection.entryPoint + "' and '" +
                          pixelReflection.entryPoint + "' (" + error.what() + ")");
    }
}

SubmissionTiming GraphicsProgram::draw(const VulkanContext& context, const DrawTargets& targets, const DrawCall& call) {
    if (targets.colors.size() != state_.colorTargets.size() || (targets.depth != nullptr) != state_.depth.has_value() ||
        targets.clearColors.size() != targets.colors.size())
        throw VulkanError("the draw's targets differ from the program's");
    if (call.vertexBuffers.size() != state_.attributes.size()) throw VulkanError("one vertex buffer per attribute");
    if (call.count == 0 || call.instances == 0) throw VulkanError("a draw of nothing (zero vertices or instances)");
    std::vector<Image*> all = targets.colors;
    if (targets.depth) all.push_back(targets.depth);
    if (all.empty()) throw VulkanError("a draw needs a render target or a depth target");
    const uint32_t width = all[0]->desc().width, height = all[0]->desc().height;
    std::vector<vk::ImageView> views;
    std::vector<vk::ClearValue> clears;
    for (size_t i = 0; i < all.size(); ++i) {
        const auto& desc = all[i]->desc();
        if (desc.width != width || desc.height != height) throw VulkanError("render targets of different sizes");
        views.push_back(all[i]->view(vk::ImageViewType::e2D, 0, 1, 0, 1));
        clears.push_back(i < targets.colors.size() ? clearValueOf(*desc.format, targets.clearColors[i])
                                                   : vk::ClearValue(vk::ClearDepthStencilValue(float(targets.clearDepth), 0)));
    }
    const vk::raii::Framebuffer framebuffer(context.device(), vk::FramebufferCreateInfo({}, *renderPass_, views, width, height, 1));
    const Viewport area = call.viewport.value_or(Viewport{0, 0, float(width), float(height)});
    bindings_.writeDescriptorSets();
    return submitTimed(
        context, [](const vk::raii::CommandBuffer&) {},
        [&](const vk::raii::CommandBuffer& commands) {
            commands.beginRenderPass(vk::RenderPassBeginInfo(*renderPass_, *framebuffer, vk::Rect2D({0, 0}, {width, height}), clears),
                                     vk::SubpassContents::eInline);
            commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
            bindings_.record(commands, vk::PipelineBindPoint::eGraphics);
            commands.setViewport(0, vk::Viewport(area.x, area.y + area.height, area.width, -area.height, area.minDepth, area.maxDepth));
            commands.setScissor(0, vk::Rect2D({0, 0}, {width, height}));
            std::vector<vk::Buffer> buffers;
            for (const auto* buffer : call.vertexBuffers) buffers.push_back(buffer->handle());
            if (!buffers.empty()) commands.bindVertexBuffers(0, buffers, std::vector<vk::DeviceSize>(buffers.size(), 0));
            if (call.indices) {
                commands.bindIndexBuffer(call.indices->handle(), 0, vk::IndexType::eUint32);
                commands.drawIndexed(call.count, call.instances, call.firstVertex, call.baseVertex, call.firstInstance);
            } else {
                commands.draw(call.count, call.instances, call.firstVertex, call.firstInstance);
            }
            commands.endRenderPass();
        },
        [](const vk::raii::CommandBuffer& commands) {
            const vk::MemoryBarrier written(vk::AccessFlagBits::eMemoryWrite, vk::AccessFlagBits::eMemoryRead | vk::AccessFlagBits::eMemoryWrite);
            commands.pipelineBarrier(vk::PipelineStageFlagBits::eAllCommands, vk::PipelineStageFlagBits::eAllCommands, {}, written, {}, {});
        });
}

} // namespace iblkit::vulkan
