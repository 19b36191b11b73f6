#include "reflection.hpp"

#include "compile_error.hpp"
#include "error_words.hpp"

#include <nlohmann/json.hpp>

namespace iblkit::compiler {
namespace {

using nlohmann::json;

json membersJson(const std::vector<BlockMember>& members) {
    json array = json::array();
    for (const auto& member : members)
        array.push_back({{"name", member.name}, {"type", member.type}, {"offset", member.offset}, {"size", member.size}});
    return array;
}

std::vector<BlockMember> membersFrom(const json& array) {
    std::vector<BlockMember> members;
    for (const auto& member : array)
        members.push_back({member.at("name"), member.at("type"), member.at("offset"), member.at("size")});
    return members;
}

ResourceKind kindNamed(const std::string& name) {
    for (const auto kind : {ResourceKind::ConstantBuffer, ResourceKind::Texture, ResourceKind::Sampler, ResourceKind::StorageImage,
                            ResourceKind::StorageBuffer, ResourceKind::TexelBuffer, ResourceKind::StorageTexelBuffer})
        if (resourceKindName(kind) == name) return kind;
    throw CompileError("reflection: unknown resource kind '" + name + "'");
}

// A resource bound by [[vk::binding]] has no register; its class is its kind's.
RegisterClass classOfKind(ResourceKind kind, bool readOnly) {
    switch (kind) {
    case ResourceKind::ConstantBuffer: return RegisterClass::ConstantBuffer;
    case ResourceKind::Texture:
    case ResourceKind::TexelBuffer: return RegisterClass::ShaderResource;
    case ResourceKind::Sampler: return RegisterClass::Sampler;
    case ResourceKind::StorageBuffer: return readOnly ? RegisterClass::ShaderResource : RegisterClass::UnorderedAccess;
    default: return RegisterClass::UnorderedAccess;
    }
}

ResourceRegister locationFrom(const ReflectedResource& resource, const json& entry) {
    ResourceRegister location{resource.name, classOfKind(resource.kind, resource.readOnly), 0, entry.at("count"), 0,
                              entry.at("explicit_register"), entry.at("set"), entry.at("binding"), entry.at("vk_binding")};
    if (location.vulkanBinding) return location;
    const std::string registerName = entry.at("register");
    const auto registerClass = registerName.empty() ? std::nullopt : registerClassFromLetter(registerName[0]);
    if (!registerClass) throw CompileError("reflection: bad register '" + registerName + "'");
    location.registerClass = *registerClass;
    location.registerIndex = uint32_t(std::stoul(registerName.substr(1)));
    location.space = entry.at("space");
    return location;
}

ReflectedResource resourceFrom(const json& entry) {
    ReflectedResource resource;
    resource.name = entry.at("name");
    resource.kind = kindNamed(entry.at("kind"));
    resource.dimension = entry.value("dimension", "");
    resource.componentType = entry.value("component_type", "");
    resource.format = entry.value("format", "");
    resource.vulkanFormat = entry.value("vulkan_format", "");
    resource.readOnly = entry.value("read_only", false);
    resource.blockSize = entry.value("size", 0u);
    if (entry.contains("members")) resource.members = membersFrom(entry.at("members"));
    resource.location = locationFrom(resource, entry);
    return resource;
}

} // namespace

nlohmann::json toJson(const ShaderReflection& reflection) {
    json resources = json::array();
    for (const auto& resource : reflection.resources) {
        const auto& location = resource.location;
        json entry = {{"name", resource.name},
                      {"kind", resourceKindName(resource.kind)},
                      {"register", location.vulkanBinding ? json(nullptr) : json(location.registerName())},
                      {"space", location.vulkanBinding ? json(nullptr) : json(location.space)},
                      {"explicit_register", location.explicitRegister},
                      {"vk_binding", location.vulkanBinding},
                      {"count", location.count},
                      {"set", location.set},
                      {"binding", location.binding}};
        if (!resource.dimension.empty()) { // images and texel buffers
            entry["dimension"] = resource.dimension;
            entry["component_type"] = resource.componentType;
            entry["format"] = resource.format;
            entry["vulkan_format"] = resource.vulkanFormat;
        }
        if (resource.kind == ResourceKind::ConstantBuffer || resource.kind == ResourceKind::StorageBuffer) {
            entry["size"] = resource.blockSize;
            entry["members"] = membersJson(resource.members);
        }
        if (resource.kind == ResourceKind::StorageBuffer) entry["read_only"] = resource.readOnly;
        resources.push_back(std::move(entry));
    }
    json specialization = json::array();
    for (const auto& constant : reflection.specializationConstants)
        specialization.push_back({{"name", constant.name}, {"constant_id", constant.constantId},
                                  {"type", constant.type}, {"default", constant.defaultValue}});
    json out = {{"entry_point", reflection.entryPoint},
                {"stage", stageName(reflection.stage)},
                {"resources", std::move(resources)},
                {"push_constants", {{"block", reflection.pushConstantBlock},
                                    {"size", reflection.pushConstantSize},
                                    {"members", membersJson(reflection.pushConstants)}}},
                {"specialization_constants", std::move(specialization)}};
    if (reflection.stage == ShaderStage::Compute) out["workgroup_size"] = reflection.workgroupSize;
    return out;
}

ShaderReflection reflectionFromJson(const nlohmann::json& object) {
    try {
        ShaderReflection reflection;
        reflection.entryPoint = object.at("entry_point");
        const std::string stage = object.at("stage");
        const auto parsedStage = parseStageName(stage);
        if (!parsedStage) throw CompileError("reflection: unknown stage '" + stage + "'");
        reflection.stage = *parsedStage;
        if (object.contains("workgroup_size")) reflection.workgroupSize = object.at("workgroup_size");
        for (const auto& entry : object.at("resources")) reflection.resources.push_back(resourceFrom(entry));
        const auto& push = object.at("push_constants");
        reflection.pushConstantBlock = push.at("block");
        reflection.pushConstantSize = push.at("size");
        reflection.pushConstants = membersFrom(push.at("members"));
        for (const auto& constant : object.at("specialization_constants"))
            reflection.specializationConstants.push_back(
                {constant.at("name"), constant.at("constant_id"), constant.at("type"), constant.at("default")});
        return reflection;
    } catch (const nlohmann::json::exception& error) {
        throw CompileError(std::string("reflection: ") + files::jsonErrorInWords(error));
    }
}

} // namespace iblkit::compiler
