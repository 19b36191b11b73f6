#include "vulkan_engine.hpp"

#include "compute_program.hpp"
#include "graphics_program.hpp"
#include "vulkan_error.hpp"

#include <fmt/core.h>

#include <variant>

namespace iblkit::run {
namespace {

vk::PrimitiveTopology vkTopologyOf(const std::string& name) {
    if (name == "triangle_strip") return vk::PrimitiveTopology::eTriangleStrip;
    if (name == "line_list") return vk::PrimitiveTopology::eLineList;
    if (name == "line_strip") return vk::PrimitiveTopology::eLineStrip;
    if (name == "point_list") return vk::PrimitiveTopology::ePointList;
    return vk::PrimitiveTopology::eTriangleList;
}

vk::CompareOp vkCompareOf(const std::string& test) {
    if (test == "never") return vk::CompareOp::eNever;
    if (test == "equal") return vk::CompareOp::eEqual;
    if (test == "less_equal") return vk::CompareOp::eLessOrEqual;
    if (test == "greater") return vk::CompareOp::eGreater;
    if (test == "not_equal") return vk::CompareOp::eNotEqual;
    if (test == "greater_equal") return vk::CompareOp::eGreaterOrEqual;
    if (test == "always") return vk::CompareOp::eAlways;
    return vk::CompareOp::eLess;
}

vulkan::BlendMode vkBlendOf(const std::string& blend) {
    if (blend == "alpha") return vulkan::BlendMode::Alpha;
    if (blend == "premultiplied") return vulkan::BlendMode::Premultiplied;
    if (blend == "additive") return vulkan::BlendMode::Additive;
    return vulkan::BlendMode::None;
}

vk::Format vertexFormatOf(const VertexFormat& format) {
    using K = vulkan::ComponentKind;
    static const vk::Format floats[] = {vk::Format::eR32Sfloat, vk::Format::eR32G32Sfloat, vk::Format::eR32G32B32Sfloat,
                                        vk::Format::eR32G32B32A32Sfloat};
    static const vk::Format uints[] = {vk::Format::eR32Uint, vk::Format::eR32G32Uint, vk::Format::eR32G32B32Uint,
                                       vk::Format::eR32G32B32A32Uint};
    static const vk::Format sints[] = {vk::Format::eR32Sint, vk::Format::eR32G32Sint, vk::Format::eR32G32B32Sint,
                                       vk::Format::eR32G32B32A32Sint};
    const uint32_t i = format.components - 1;
    switch (format.kind) {
    case K::UInt: return uints[i];
    case K::SInt: return sints[i];
    case K::UNorm: return vk::Format::eR8G8B8A8Unorm;
    case K::Float: break;
    }
    return floats[i];
}

vulkan::SamplerDesc samplerDescOf(const ResourceSpec& spec) {
    vulkan::SamplerDesc desc;
    desc.filter = spec.filter == "nearest" ? vk::Filter::eNearest : vk::Filter::eLinear;
    desc.mipmap = spec.mipmap == "nearest" ? vk::SamplerMipmapMode::eNearest : vk::SamplerMipmapMode::eLinear;
    desc.address = spec.address == "repeat"   ? vk::SamplerAddressMode::eRepeat
                   : spec.address == "mirror" ? vk::SamplerAddressMode::eMirroredRepeat
                                              : vk::SamplerAddressMode::eClampToEdge;
    return desc;
}

class VulkanEngine final : public RunEngine {
public:
    explicit VulkanEngine(const RunOptions& options)
        : log_(std::make_shared<vulkan::ValidationLog>()),
          context_({options.device, options.validation, log_, options.timeout, options.onDeviceFailure}) {}

    std::string apiName() const override { return "vulkan"; }
    std::string deviceLine() const override {
        return context_.deviceInfo().name + (context_.validationEnabled() ? ", validation on" : "");
    }

    void makeProgram(const RunSpec& spec, const RunPrograms& programs, const DrawPlan* draw) override {
        if (!draw) {
            program_.emplace<vulkan::ComputeProgram>(context_, programs.compute->spirv, programs.compute->reflection,
                                                     spec.specialization);
            return;
        }
        vulkan::GraphicsStateDesc state;
        for (const auto& attribute : draw->attributes)
            state.attributes.push_back({attribute.location, vertexFormatOf(*attribute.format), attribute.format->bytesPerVertex()});
        for (const auto& target : draw->targets)
            state.colorTargets.push_back({target.location, target.shape.format, vkBlendOf(target.spec->blend)});
        const auto& graphics = *draw->spec;
        if (graphics.depth) state.depth = vulkan::DepthTargetDesc{vkCompareOf(graphics.depth->test), graphics.depth->write};
        state.topology = vkTopologyOf(graphics.draw.topology);
        state.cull = graphics.cull == "back"    ? vk::CullModeFlagBits::eBack
                     : graphics.cull == "front" ? vk::CullModeFlagBits::eFront
                                                : vk::CullModeFlagBits::eNone;
        state.frontClockwise = graphics.front == "clockwise";
        program_.emplace<vulkan::GraphicsProgram>(context_, programs.vertex->spirv, programs.vertex->reflection,
                                                  programs.pixel->spirv, programs.pixel->reflection, state, spec.specialization);
    }

    void makeResource(const ResourcePlan& plan) override {
        const auto& spec = *plan.spec;
        if (spec.kind == "cbuffer" || spec.kind == "buffer") {
            const auto usage = spec.kind == "cbuffer" ? vk::BufferUsageFlagBits::eUniformBuffer : vk::BufferUsageFlagBits::eStorageBuffer;
            auto buffer = std::make_unique<vulkan::Buffer>(context_, plan.bufferSize, usage, spec.name);
            buffer->write(plan.contents());
            bind(spec.binding, *buffer, spec.element);
            formats_[spec.name] = plan.format;
            resources_[spec.name] = std::move(buffer);
        } else if (spec.kind == "sampler") {
            auto sampler = std::make_unique<vulkan::Sampler>(context_, samplerDescOf(spec));
            bind(spec.binding, *sampler, spec.element);
            resources_[spec.name] = std::move(sampler);
        } else {
            const auto& shape = *plan.image;
            auto image = std::make_unique<vulkan::Image>(
                context_, vulkan::ImageDesc{spec.name, shape.format, shape.width, shape.height, shape.layers, shape.mips,
                                            shape.cube, spec.kind == "storage_image"});
            image->uploadBytes(context_, plan.contents());
            std::visit([&](auto& program) {
                if constexpr (!std::is_same_v<std::decay_t<decltype(program)>, std::monostate>)
                    program.bind(spec.binding, *image, spec.mip, spec.element);
            }, program_);
            resources_[spec.name] = std::move(image);
        }
    }

    void setPushConstants(std::span<const std::byte> bytes) override {
        std::visit([&](auto& program) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(program)>, std::monostate>) program.setPushConstants(bytes);
        }, program_);
    }

    std::string execute(const RunSpec& spec, const DrawPlan* draw) override {
        if (!draw) {
            auto& compute = std::get<vulkan::ComputeProgram>(program_);
            const auto timing = spec.threads ? compute.dispatchThreads(context_, *spec.threads) : compute.dispatchGroups(context_, *spec.groups);
            return fmt::format("dispatch {}x{}x{} groups: {} on the device, {:.3f} ms wall", timing.groups[0], timing.groups[1],
                               timing.groups[2], deviceTime(timing.deviceMilliseconds), timing.wallMilliseconds);
        }
        return executeDraw(*draw);
    }

    Readback read(const std::string& name) override {
        const auto found = resources_.find(name);
        if (found == resources_.end()) throw vulkan::VulkanError("no resource named '" + name + "' to check or save");
        if (const auto* image = std::get_if<std::unique_ptr<vulkan::Image>>(&found->second)) {
            const auto& desc = (*image)->desc();
            const auto bytes = (*image)->downloadBytes(context_);
            Readback readback{std::vector<double>(bytes.size() / desc.format->bytesPerChannel), desc.format,
                              ImageShape{desc.format, desc.width, desc.height, desc.layers, desc.mips, desc.cube}};
            vulkan::decodeTexels(*desc.format, bytes, readback.values);
            return readback;
        }
        if (const auto* buffer = std::get_if<std::unique_ptr<vulkan::Buffer>>(&found->second)) {
            const auto& format = *formats_.at(name);
            const auto bytes = (*buffer)->read();
            Readback readback{std::vector<double>(bytes.size() / 4), &format, std::nullopt};
            vulkan::decodeTexels(format, bytes, readback.values);
            return readback;
        }
        throw vulkan::VulkanError("'" + name + "' is a sampler: it holds no values");
    }

    std::vector<std::string> validationMessages() const override { return log_->messages(); }

private:
    using Resource = std::variant<std::unique_ptr<vulkan::Buffer>, std::unique_ptr<vulkan::Image>, std::unique_ptr<vulkan::Sampler>>;

    static std::string deviceTime(double milliseconds) {
        return milliseconds >= 0 ? fmt::format("{:.3f} ms", milliseconds) : "no timestamps";
    }

    template <typename Bindable>
    void bind(const std::string& name, const Bindable& resource, uint32_t element) {
        std::visit([&](auto& program) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(program)>, std::monostate>) program.bind(name, resource, element);
        }, program_);
    }

    std::string executeDraw(const DrawPlan& draw) {
        auto& program = std::get<vulkan::GraphicsProgram>(program_);
        const auto& graphics = *draw.spec;
        vulkan::DrawTargets targets;
        for (const auto& target : draw.targets) {
            targets.colors.push_back(makeTarget(target.spec->name, target.shape));
            targets.clearColors.push_back(target.spec->clear);
        }
        if (draw.depth) {
            targets.depth = makeTarget(graphics.depth->name, *draw.depth);
            targets.clearDepth = graphics.depth->clear;
        }
        vulkan::DrawCall call;
        std::vector<std::unique_ptr<vulkan::Buffer>> vertexBuffers;
        for (const auto& attribute : draw.attributes) {
            vertexBuffers.push_back(std::make_unique<vulkan::Buffer>(context_, std::max<size_t>(attribute.bytes.size(), 4),
                                                                     vk::BufferUsageFlagBits::eVertexBuffer, attribute.semantic));
            vertexBuffers.back()->write(attribute.bytes);
            call.vertexBuffers.push_back(vertexBuffers.back().get());
        }
        std::unique_ptr<vulkan::Buffer> indices;
        if (!graphics.indices.empty()) {
            indices = std::make_unique<vulkan::Buffer>(context_, graphics.indices.size() * 4, vk::BufferUsageFlagBits::eIndexBuffer, "indices");
            indices->write(std::as_bytes(std::span(graphics.indices)));
            call.indices = indices.get();
        }
        call.count = draw.count;
        call.instances = graphics.draw.instances;
        call.firstVertex = graphics.draw.firstVertex;
        call.firstInstance = graphics.draw.firstInstance;
        call.baseVertex = graphics.draw.baseVertex;
        if (const auto& v = graphics.viewport) call.viewport = vulkan::Viewport{float((*v)[0]), float((*v)[1]), float((*v)[2]),
                                                                                float((*v)[3]), float((*v)[4]), float((*v)[5])};
        const auto timing = program.draw(context_, targets, call);
        return fmt::format("draw {} {} x {} instance{}: {} on the device, {:.3f} ms wall", draw.count,
                           graphics.indices.empty() ? "vertices" : "indices", call.instances, call.instances == 1 ? "" : "s",
                           deviceTime(timing.deviceMilliseconds), timing.wallMilliseconds);
    }

    // A target the device cannot render is named by its key.
    vulkan::Image* makeTarget(const std::string& name, const ImageShape& shape) {
        std::unique_ptr<vulkan::Image> image;
        try {
            image = std::make_unique<vulkan::Image>(
                context_, vulkan::ImageDesc{name, shape.format, shape.width, shape.height, 1, 1, false, false, true});
        } catch (const vulkan::VulkanError& error) {
            throw vulkan::VulkanError("targets." + name + ": " + error.what());
        }
        auto* raw = image.get();
        resources_[name] = std::move(image);
        return raw;
    }

    std::shared_ptr<vulkan::ValidationLog> log_;
    vulkan::VulkanContext context_;
    std::variant<std::monostate, vulkan::ComputeProgram, vulkan::GraphicsProgram> program_;
    std::map<std::string, Resource> resources_;
    std::map<std::string, const vulkan::TexelFormat*> formats_;
};

} // namespace

std::unique_ptr<RunEngine> makeVulkanEngine(const RunOptions& options) { return std::make_unique<VulkanEngine>(options); }

} // namespace iblkit::run
