#include "opengl_engine.hpp"

#include "compiler.hpp"
#include "cross_compile.hpp"
#include "gl_error.hpp"
#include "gl_object.hpp"
#include "gl_formats.hpp"
#include "block_writer.hpp"

#include <fmt/core.h>

#include <cctype>
#include <chrono>
#include <cstring>
#include <map>

namespace iblkit::run {
namespace {

using opengl::GlError;
using opengl::GlObject;

GLenum glTopologyOf(const std::string& name) {
    if (name == "triangle_strip") return GL_TRIANGLE_STRIP;
    if (name == "line_list") return GL_LINES;
    if (name == "line_strip") return GL_LINE_STRIP;
    if (name == "point_list") return GL_POINTS;
    return GL_TRIANGLES;
}

GLenum glCompareOf(const std::string& test) {
    if (test == "never") return GL_NEVER;
    if (test == "equal") return GL_EQUAL;
    if (test == "less_equal") return GL_LEQUAL;
    if (test == "greater") return GL_GREATER;
    if (test == "not_equal") return GL_NOTEQUAL;
    if (test == "greater_equal") return GL_GEQUAL;
    if (test == "always") return GL_ALWAYS;
    return GL_LESS;
}

struct GlForm {
    compiler::CrossCompiled glsl;
    std::string name;
};

// SPIRV-Cross writes each specialization constant as a macro with its default, for the
// program to define first: "#define SPIRV_CROSS_CONSTANT_ID_3 5u" after the #version line.
std::string specialized(const std::string& source, const compiler::ShaderReflection& reflection,
                        const std::map<std::string, double>& values) {
    std::string defines;
    for (const auto& constant : reflection.specializationConstants) {
        const auto value = values.find(constant.name);
        if (value == values.end()) continue;
        const std::string literal = constant.type == "float"  ? fmt::format("{:.9e}", value->second)
                                    : constant.type == "bool" ? (value->second != 0 ? "true" : "false")
                                    : constant.type == "int"  ? fmt::format("{}", int64_t(value->second))
                                                              : fmt::format("{}u", uint64_t(value->second));
        defines += fmt::format("#define SPIRV_CROSS_CONSTANT_ID_{} {}\n", constant.constantId, literal);
    }
    const size_t afterVersion = source.find('\n') + 1;
    return source.substr(0, afterVersion) + defines + source.substr(afterVersion);
}

GlForm glslFormOf(const ShaderProgram& program, const std::map<std::string, double>& specialization) {
    compiler::CrossCompiled glsl;
    try {
        glsl = compiler::crossCompile(program.namedSpirv, program.reflection, compiler::CrossTarget::Glsl, program.sourceName);
    } catch (const std::exception& error) {
        throw GlError(std::string("the GLSL form cannot be made: ") + error.what());
    }
    glsl.source = specialized(glsl.source, program.reflection, specialization);
    return {glsl, program.sourceName + " (" + program.reflection.entryPoint + ")"};
}

struct GlBuffer {
    GlObject object;
    const vulkan::TexelFormat* format;
    size_t bytes;
};

struct Texture {
    GlObject object;
    ImageShape shape;
    GLenum target;
};

class OpenGlEngine final : public RunEngine {
public:
    std::string apiName() const override { return "opengl"; }
    std::string deviceLine() const override { return context_.renderer(); }

    void makeProgram(const RunSpec& spec, const RunPrograms& programs, const DrawPlan* draw) override {
        const auto& gl = context_.gl();
        gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        if (!draw) {
            forms_.push_back(glslFormOf(*programs.compute, spec.specialization));
            program_.emplace(opengl::createComputeProgram(context_, forms_[0].glsl.source, forms_[0].name + " (GLSL)"));
            workgroup_ = programs.compute->reflection.workgroupSize;
        } else {
            forms_.push_back(glslFormOf(*programs.vertex, spec.specialization));
            forms_.push_back(glslFormOf(*programs.pixel, spec.specialization));
            program_.emplace(opengl::createGraphicsProgram(context_, forms_[0].glsl.source, forms_[1].glsl.source,
                                                           forms_[0].name + " and " + forms_[1].name + " (GLSL)"));
        }
        pushConstants_ = programs.resources;
    }

    void makeResource(const ResourcePlan& plan) override {
        const auto& spec = *plan.spec;
        const auto& gl = context_.gl();
        if (spec.kind == "cbuffer" || spec.kind == "buffer") {
            auto buffer = opengl::createBuffer(context_);
            std::vector<std::byte> contents(plan.bufferSize);
            const auto initial = plan.contents();
            std::copy(initial.begin(), initial.end(), contents.begin());
            gl.NamedBufferData(buffer.name(), GLsizeiptr(contents.size()), contents.data(), GL_DYNAMIC_COPY);
            for (const auto slot : slotsOf(spec.binding, spec.kind == "cbuffer" ? "uniform_block" : "storage_buffer", spec.element))
                gl.BindBufferBase(spec.kind == "cbuffer" ? GL_UNIFORM_BUFFER : GL_SHADER_STORAGE_BUFFER, slot, buffer.name());
            context_.check(("binding " + spec.name).c_str());
            buffers_.emplace(spec.name, GlBuffer{std::move(buffer), plan.format, plan.bufferSize});
        } else if (spec.kind == "sampler") {
            samplers_.emplace(spec.name, makeSampler(spec));
        } else {
            textures_.emplace(spec.name, makeTexture(spec, *plan.image, plan.contents()));
            if (spec.kind == "storage_image") {
                const auto& texture = textures_.at(spec.name);
                const auto& format = glTexelFormatOf(*texture.shape.format);
                for (const auto slot : slotsOf(spec.binding, "image_unit", spec.element))
                    gl.BindImageTexture(slot, texture.object.name(), GLint(spec.mip), texture.shape.layers > 1 ? GL_TRUE : GL_FALSE, 0,
                                        GL_READ_WRITE, format.internalFormat);
                context_.check(("binding " + spec.name).c_str());
            }
        }
    }

    // OpenGL has no push constants: the GLSL form declares the block as a uniform struct at
    // location 0, one location per member.
    void setPushConstants(std::span<const std::byte> bytes) override {
        const auto& gl = context_.gl();
        GLint location = 0;
        for (const auto& member : pushConstants_.pushConstants) {
            const std::string& type = member.type;
            const bool vector = std::isdigit(static_cast<unsigned char>(type.back())) != 0;
            if (type.find_first_of("x[") != std::string::npos)
                throw GlError("push constant '" + member.name + "' is a " + type +
                              ": the OpenGL runner sets scalars and vectors of the push constant block");
            const auto count = vector ? type.back() - '0' : 1;
            const std::string scalar = vector ? type.substr(0, type.size() - 1) : type;
            std::array<uint32_t, 4> words{};
            std::memcpy(words.data(), bytes.data() + member.offset, size_t(count) * 4);
            const GLuint program = program_->name();
            if (scalar == "float") {
                std::array<float, 4> values{};
                std::memcpy(values.data(), words.data(), 16);
                const std::array set{gl.ProgramUniform1fv, gl.ProgramUniform2fv, gl.ProgramUniform3fv, gl.ProgramUniform4fv};
                set[size_t(count - 1)](program, location, 1, values.data());
            } else if (scalar == "int") {
                std::array<GLint, 4> values{};
                std::memcpy(values.data(), words.data(), 16);
                const std::array set{gl.ProgramUniform1iv, gl.ProgramUniform2iv, gl.ProgramUniform3iv, gl.ProgramUniform4iv};
                set[size_t(count - 1)](program, location, 1, values.data());
            } else if (scalar == "uint" || scalar == "bool") {
                const std::array set{gl.ProgramUniform1uiv, gl.ProgramUniform2uiv, gl.ProgramUniform3uiv, gl.ProgramUniform4uiv};
                set[size_t(count - 1)](program, location, 1, words.data());
            } else {
                throw GlError("push constant '" + member.name + "' is a " + type + ", which the OpenGL runner does not set");
            }
            ++location;
        }
        context_.check("setting the push constants");
    }

    std::string execute(const RunSpec& spec, const DrawPlan* draw) override {
        bindTextures();
        const auto& gl = context_.gl();
        gl.UseProgram(program_->name());
        const auto start = std::chrono::steady_clock::now();
        std::string line;
        if (!draw) {
            std::array<GLuint, 3> groups{};
            for (int axis = 0; axis < 3; ++axis) {
                const uint32_t size = std::max(1u, workgroup_[axis]);
                groups[axis] = spec.threads ? ((*spec.threads)[axis] + size - 1) / size : (*spec.groups)[axis];
            }
            gl.DispatchCompute(groups[0], groups[1], groups[2]);
            line = fmt::format("dispatch {}x{}x{} groups", groups[0], groups[1], groups[2]);
        } else {
            line = drawWith(*draw);
        }
        gl.MemoryBarrier(GL_ALL_BARRIER_BITS);
        gl.Finish();
        context_.check("the run");
        const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return fmt::format("{}: {:.3f} ms wall", line, wall);
    }

    Readback read(const std::string& name) override {
        const auto& gl = context_.gl();
        if (const auto found = textures_.find(name); found != textures_.end()) {
            const auto& texture = found->second;
            const auto& format = glTexelFormatOf(*texture.shape.format);
            std::vector<std::byte> bytes(texture.shape.valueCount() * texture.shape.format->bytesPerChannel);
            for (uint32_t mip = 0; mip < texture.shape.mips; ++mip) {
                const size_t begin = texture.shape.valueOffset(mip, 0) * texture.shape.format->bytesPerChannel;
                const size_t end = texture.shape.valueOffset(mip + 1, 0) * texture.shape.format->bytesPerChannel;
                gl.GetTextureImage(texture.object.name(), GLint(mip), format.format, format.type, GLsizei(end - begin), bytes.data() + begin);
            }
            context_.check(("reading " + name).c_str());
            Readback readback{std::vector<double>(texture.shape.valueCount()), texture.shape.format, texture.shape};
            vulkan::decodeTexels(*texture.shape.format, bytes, readback.values);
            return readback;
        }
        if (const auto found = buffers_.find(name); found != buffers_.end()) {
            const auto& [buffer, format, size] = found->second;
            std::vector<std::byte> bytes(size);
            gl.GetNamedBufferSubData(buffer.name(), 0, GLsizeiptr(bytes.size()), bytes.data());
            context_.check(("reading " + name).c_str());
            Readback readback{std::vector<double>(bytes.size() / 4), format, std::nullopt};
            vulkan::decodeTexels(*format, bytes, readback.values);
            return readback;
        }
        throw GlError("no resource named '" + name + "' to check or save");
    }

private:
    // Where the GLSL forms put an HLSL resource in a namespace: one slot per form that uses it.
    std::vector<GLuint> slotsOf(const std::string& resource, const std::string& space, uint32_t element) const {
        std::vector<GLuint> slots;
        for (const auto& form : forms_)
            for (const auto& binding : form.glsl.bindings)
                if (binding.resource == resource && binding.namespace_ == space) slots.push_back(binding.slot + element);
        return slots;
    }

    GlObject makeSampler(const ResourceSpec& spec) const {
        const auto& gl = context_.gl();
        auto sampler = opengl::createSampler(context_);
        const bool nearest = spec.filter == "nearest", nearestMip = spec.mipmap == "nearest";
        gl.SamplerParameteri(sampler.name(), GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
        gl.SamplerParameteri(sampler.name(), GL_TEXTURE_MIN_FILTER,
                             nearest ? (nearestMip ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_LINEAR)
                                     : (nearestMip ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR));
        const GLint wrap = spec.address == "repeat" ? GL_REPEAT : spec.address == "mirror" ? GL_MIRRORED_REPEAT : GL_CLAMP_TO_EDGE;
        for (GLenum axis : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) gl.SamplerParameteri(sampler.name(), axis, wrap);
        context_.check(("making sampler " + spec.name).c_str());
        return sampler;
    }

    Texture makeTexture(const ResourceSpec& spec, const ImageShape& shape, std::span<const std::byte> bytes) {
        const auto& gl = context_.gl();
        const auto& format = glTexelFormatOf(*shape.format);
        // A written cube is a 2D array of six layers, as the GLSL form declares it (image2DArray).
        const GLenum target = shape.cube && spec.kind != "storage_image" ? GL_TEXTURE_CUBE_MAP
                              : shape.layers > 1 || spec.dimension == "2d_array" ? GL_TEXTURE_2D_ARRAY
                                                                                  : GL_TEXTURE_2D;
        Texture texture{opengl::createTexture(context_, target), shape, target};
        const auto w = GLsizei(shape.width), h = GLsizei(shape.height);
        if (target == GL_TEXTURE_2D_ARRAY) gl.TextureStorage3D(texture.object.name(), GLsizei(shape.mips), format.internalFormat, w, h, GLsizei(shape.layers));
        else gl.TextureStorage2D(texture.object.name(), GLsizei(shape.mips), format.internalFormat, w, h);
        for (uint32_t mip = 0; mip < shape.mips && !bytes.empty(); ++mip) {
            const auto* at = bytes.data() + shape.valueOffset(mip, 0) * shape.format->bytesPerChannel;
            const auto mw = GLsizei(shape.mipWidth(mip)), mh = GLsizei(shape.mipHeight(mip));
            if (target == GL_TEXTURE_2D) gl.TextureSubImage2D(texture.object.name(), GLint(mip), 0, 0, mw, mh, format.format, format.type, at);
            else gl.TextureSubImage3D(texture.object.name(), GLint(mip), 0, 0, 0, mw, mh, GLsizei(shape.layers), format.format, format.type, at);
        }
        gl.TextureParameteri(texture.object.name(), GL_TEXTURE_MAX_LEVEL, GLint(shape.mips - 1));
        context_.check(("making image " + spec.name).c_str());
        return texture;
    }

    // Each combined texture unit "Texture+Sampler" gets the texture and the sampler object.
    void bindTextures() const {
        const auto& gl = context_.gl();
        for (const auto& form : forms_)
            for (const auto& binding : form.glsl.bindings) {
                if (binding.namespace_ != "texture_unit") continue;
                const auto plus = binding.resource.find('+');
                const std::string textureName = binding.resource.substr(0, plus);
                const auto sampler = plus == std::string::npos ? samplers_.end() : samplers_.find(binding.resource.substr(plus + 1));
                const auto bindUnit = [&](GLuint slot, const Texture& texture) {
                    gl.BindTextureUnit(slot, texture.object.name());
                    gl.BindSampler(slot, sampler != samplers_.end() ? sampler->second.name() : 0);
                };
                if (const auto texture = textures_.find(textureName); texture != textures_.end()) {
                    bindUnit(binding.slot, texture->second);
                    continue;
                }
                // An array of textures: its elements, named "Name[i]", at consecutive units.
                for (uint32_t element = 0;; ++element) {
                    const auto texture = textures_.find(textureName + "[" + std::to_string(element) + "]");
                    if (texture == textures_.end()) break;
                    bindUnit(binding.slot + element, texture->second);
                }
            }
        context_.check("binding the textures");
    }

    std::string drawWith(const DrawPlan& draw);
    const Texture& makeTarget(const std::string& name, const ImageShape& shape);

    opengl::EglContext context_;
    std::vector<GlForm> forms_;
    std::optional<GlObject> program_;
    std::array<uint32_t, 3> workgroup_{1, 1, 1};
    compiler::ShaderReflection pushConstants_;
    std::map<std::string, GlBuffer> buffers_;
    std::map<std::string, GlObject> samplers_;
    std::map<std::string, Texture> textures_;
    std::vector<GlObject> drawObjects_;
};


std::string OpenGlEngine::drawWith(const DrawPlan& draw) {
    const auto& gl = context_.gl();
    const auto& graphics = *draw.spec;
    auto framebuffer = opengl::createFramebuffer(context_);
    std::vector<GLenum> drawBuffers;
    for (const auto& target : draw.targets) {
        const auto& texture = makeTarget(target.spec->name, target.shape);
        gl.NamedFramebufferTexture(framebuffer.name(), GL_COLOR_ATTACHMENT0 + target.location, texture.object.name(), 0);
        drawBuffers.resize(std::max<size_t>(drawBuffers.size(), target.location + 1), GL_NONE);
        drawBuffers[target.location] = GL_COLOR_ATTACHMENT0 + target.location;
    }
    if (draw.depth)
        gl.NamedFramebufferTexture(framebuffer.name(), GL_DEPTH_ATTACHMENT, makeTarget(graphics.depth->name, *draw.depth).object.name(), 0);
    gl.NamedFramebufferDrawBuffers(framebuffer.name(), GLsizei(drawBuffers.size()), drawBuffers.data());
    if (gl.CheckNamedFramebufferStatus(framebuffer.name(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("targets: OpenGL cannot render to these targets together (the framebuffer is incomplete)");
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
    // Direct3D's conventions: NDC y = +1 on the first row, gl_FragCoord from the top, depth 0 to 1.
    gl.ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    // A nointerpolation value comes from a primitive's first vertex, as in Direct3D and Vulkan.
    gl.ProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    for (const auto& target : draw.targets) {
        const auto& clear = target.spec->clear;
        const auto drawBuffer = GLint(target.location);
        if (target.shape.format->kind == vulkan::ComponentKind::UInt) {
            const GLuint value[4] = {GLuint(clear[0]), GLuint(clear[1]), GLuint(clear[2]), GLuint(clear[3])};
            gl.ClearNamedFramebufferuiv(framebuffer.name(), GL_COLOR, drawBuffer, value);
        } else if (target.shape.format->kind == vulkan::ComponentKind::SInt) {
            const GLint value[4] = {GLint(clear[0]), GLint(clear[1]), GLint(clear[2]), GLint(clear[3])};
            gl.ClearNamedFramebufferiv(framebuffer.name(), GL_COLOR, drawBuffer, value);
        } else {
            const GLfloat value[4] = {GLfloat(clear[0]), GLfloat(clear[1]), GLfloat(clear[2]), GLfloat(clear[3])};
            gl.ClearNamedFramebufferfv(framebuffer.name(), GL_COLOR, drawBuffer, value);
        }
        if (target.spec->blend == "none") {
            gl.Disablei(GL_BLEND, target.location);
            continue;
        }
        gl.Enablei(GL_BLEND, target.location);
        gl.BlendEquationi(target.location, GL_FUNC_ADD);
        if (target.spec->blend == "alpha") gl.BlendFunci(target.location, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        else if (target.spec->blend == "premultiplied") gl.BlendFunci(target.location, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        else gl.BlendFunci(target.location, GL_ONE, GL_ONE);
    }
    if (draw.depth) {
        gl.DepthMask(GL_TRUE); // a clear writes depth only where writes are on
        const GLfloat clear = GLfloat(graphics.depth->clear);
        gl.ClearNamedFramebufferfv(framebuffer.name(), GL_DEPTH, 0, &clear);
        gl.Enable(GL_DEPTH_TEST);
        gl.DepthFunc(glCompareOf(graphics.depth->test));
        gl.DepthMask(graphics.depth->write ? GL_TRUE : GL_FALSE);
    } else {
        gl.Disable(GL_DEPTH_TEST);
    }
    if (graphics.cull == "none") {
        gl.Disable(GL_CULL_FACE);
    } else {
        gl.Enable(GL_CULL_FACE);
        gl.CullFace(graphics.cull == "back" ? GL_BACK : GL_FRONT);
    }
    // With the upper-left origin OpenGL decides the winding as it appears in the target.
    gl.FrontFace(graphics.front == "clockwise" ? GL_CW : GL_CCW);
    const auto& shape = draw.targets.empty() ? *draw.depth : draw.targets[0].shape;
    const std::array<double, 6> area = graphics.viewport.value_or(std::array<double, 6>{0, 0, double(shape.width), double(shape.height), 0, 1});
    gl.ViewportIndexedf(0, GLfloat(area[0]), GLfloat(area[1]), GLfloat(area[2]), GLfloat(area[3]));
    gl.DepthRangef(GLfloat(area[4]), GLfloat(area[5]));

    auto vertexArray = opengl::createVertexArray(context_);
    for (uint32_t i = 0; i < draw.attributes.size(); ++i) {
        const auto& attribute = draw.attributes[i];
        auto buffer = opengl::createBuffer(context_);
        gl.NamedBufferData(buffer.name(), GLsizeiptr(std::max<size_t>(attribute.bytes.size(), 4)), attribute.bytes.data(), GL_STATIC_DRAW);
        const auto& format = *attribute.format;
        gl.VertexArrayVertexBuffer(vertexArray.name(), i, buffer.name(), 0, GLsizei(format.bytesPerVertex()));
        gl.EnableVertexArrayAttrib(vertexArray.name(), attribute.location);
        const auto components = GLint(format.components);
        if (format.kind == vulkan::ComponentKind::Float) gl.VertexArrayAttribFormat(vertexArray.name(), attribute.location, components, GL_FLOAT, GL_FALSE, 0);
        else if (format.kind == vulkan::ComponentKind::UNorm) gl.VertexArrayAttribFormat(vertexArray.name(), attribute.location, components, GL_UNSIGNED_BYTE, GL_TRUE, 0);
        else gl.VertexArrayAttribIFormat(vertexArray.name(), attribute.location, components, format.kind == vulkan::ComponentKind::UInt ? GL_UNSIGNED_INT : GL_INT, 0);
        gl.VertexArrayAttribBinding(vertexArray.name(), attribute.location, i);
        drawObjects_.push_back(std::move(buffer));
    }
    if (!graphics.indices.empty()) {
        auto indices = opengl::createBuffer(context_);
        gl.NamedBufferData(indices.name(), GLsizeiptr(graphics.indices.size() * 4), graphics.indices.data(), GL_STATIC_DRAW);
        gl.VertexArrayElementBuffer(vertexArray.name(), indices.name());
        drawObjects_.push_back(std::move(indices));
    }
    gl.BindVertexArray(vertexArray.name());
    const auto& call = graphics.draw;
    const GLenum mode = glTopologyOf(call.topology);
    if (graphics.indices.empty())
        gl.DrawArraysInstancedBaseInstance(mode, GLint(call.firstVertex), GLsizei(draw.count), GLsizei(call.instances), call.firstInstance);
    else
        gl.DrawElementsInstancedBaseVertexBaseInstance(mode, GLsizei(draw.count), GL_UNSIGNED_INT,
                                                       reinterpret_cast<const void*>(uintptr_t(call.firstVertex) * 4),
                                                       GLsizei(call.instances), call.baseVertex, call.firstInstance);
    drawObjects_.push_back(std::move(vertexArray));
    drawObjects_.push_back(std::move(framebuffer));
    return fmt::format("draw {} {} x {} instance{}", draw.count, graphics.indices.empty() ? "vertices" : "indices", call.instances,
                       call.instances == 1 ? "" : "s");
}

const Texture& OpenGlEngine::makeTarget(const std::string& name, const ImageShape& shape) {
    const auto& format = glTexelFormatOf(*shape.format);
    Texture texture{opengl::createTexture(context_, GL_TEXTURE_2D), shape, GL_TEXTURE_2D};
    context_.gl().TextureStorage2D(texture.object.name(), 1, format.internalFormat, GLsizei(shape.width), GLsizei(shape.height));
    context_.check(("making target " + name).c_str());
    textures_.erase(name);
    return textures_.emplace(name, std::move(texture)).first->second;
}

} // namespace

std::unique_ptr<RunEngine> makeOpenGlEngine() { return std::make_unique<OpenGlEngine>(); }

} // namespace iblkit::run
