#include "vulkan_context.hpp"

#include "vulkan_error.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace iblkit::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoDevice =
    "no Vulkan device found: install Mesa's lavapipe (Debian package mesa-vulkan-drivers) or a GPU driver";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* log) {
    static_cast<ValidationLog*>(log)->add(data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE;
}

vk::DebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
    return {{},
            vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning | vk::DebugUtilsMessageSeverityFlagBitsEXT::eError,
            vk::DebugUtilsMessageTypeFlagBitsEXT::eGeneral | vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation |
                vk::DebugUtilsMessageTypeFlagBitsEXT::ePerformance,
            &onValidationMessage, log};
}

bool layerAvailable(const vk::raii::Context& loader, const char* name) {
    const auto layers = loader.enumerateInstanceLayerProperties();
    return std::any_of(layers.begin(), layers.end(), [&](const auto& layer) { return std::string(layer.layerName) == name; });
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::string typeName(vk::PhysicalDeviceType type) {
    switch (type) {
    case vk::PhysicalDeviceType::eCpu: return "cpu";
    case vk::PhysicalDeviceType::eDiscreteGpu: return "discrete-gpu";
    case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated-gpu";
    case vk::PhysicalDeviceType::eVirtualGpu: return "virtual-gpu";
    default: return "other";
    }
}

DeviceInfo describe(const vk::raii::PhysicalDevice& device, uint32_t index) {
    const auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>();
    const auto& properties = chain.get<vk::PhysicalDeviceProperties2>().properties;
    const auto& driver = chain.get<vk::PhysicalDeviceDriverProperties>();
    const std::string name = properties.deviceName.data();
    return {index,
            name,
            typeName(properties.deviceType),
            std::string(driver.driverName.data()) + " " + driver.driverInfo.data(),
            std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
                std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + "." +
                std::to_string(VK_API_VERSION_PATCH(properties.apiVersion)),
            driver.driverID == vk::DriverId::eMesaLlvmpipe};
}

vk::raii::Instance createInstance(const vk::raii::Context& loader, bool validation, ValidationLog* log) {
    const vk::ApplicationInfo application("iblkit", 1, "iblkit", 1, VK_API_VERSION_1_1);
    std::vector<const char*> layers, extensions;
    if (validation) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    vk::InstanceCreateInfo info({}, &application, layers, extensions);
    // Chained so that instance creation and destruction are reported too.
    const auto debugInfo = messengerInfo(log);
    if (validation) info.pNext = &debugInfo;
    try {
        return vk::raii::Instance(loader, info);
    } catch (const vk::IncompatibleDriverError&) {
        throw VulkanError(kNoDevice);
    }
}

std::vector<vk::raii::PhysicalDevice> physicalDevicesOf(const vk::raii::Instance& instance) {
    try {
        vk::raii::PhysicalDevices devices(instance);
        if (devices.empty()) throw VulkanError(kNoDevice);
        return {devices.begin(), devices.end()};
    } catch (const vk::InitializationFailedError&) {
        throw VulkanError(kNoDevice);
    }
}

vk::raii::Context loadVulkan() {
    try {
        return vk::raii::Context();
    } catch (const std::runtime_error&) {
        throw VulkanError("cannot load the Vulkan loader: install Debian packages libvulkan1 and mesa-vulkan-drivers");
    }
}

} // namespace

size_t chooseDevice(const std::vector<DeviceInfo>& devices, const std::string& requested) {
    const char* fromEnvironment = std::getenv("IBLKIT_DEVICE");
    const std::string selector = !requested.empty() ? requested : fromEnvironment ? fromEnvironment : "";
    if (selector.empty()) {
        for (size_t i = 0; i < devices.size(); ++i)
            if (devices[i].isLavapipe) return i;
        return 0;
    }
    if (std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); })) {
        const size_t index = selector.size() < 10 ? std::stoul(selector) : devices.size();
        if (index < devices.size()) return index;
        throw VulkanError("no Vulkan device has index " + selector + " (there are " + std::to_string(devices.size()) +
                          "; see iblkit devices)");
    }
    for (size_t i = 0; i < devices.size(); ++i)
        if (lowercase(devices[i].name).find(lowercase(selector)) != std::string::npos) return i;
    throw VulkanError("no Vulkan device matches '" + selector + "' (see iblkit devices)");
}

namespace {

bool hasDeviceExtension(const vk::raii::PhysicalDevice& device, std::string_view name) {
    const auto extensions = device.enumerateDeviceExtensionProperties();
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const vk::ExtensionProperties& extension) { return name == extension.extensionName.data(); });
}

// A queue that draws as well, where there is one: every GPU and lavapipe have it.
uint32_t computeQueueFamily(const vk::raii::PhysicalDevice& device) {
    const auto families = device.getQueueFamilyProperties();
    const auto both = vk::QueueFlagBits::eCompute | vk::QueueFlagBits::eGraphics;
    for (uint32_t i = 0; i < families.size(); ++i)
        if ((families[i].queueFlags & both) == both) return i;
    for (uint32_t i = 0; i < families.size(); ++i)
        if (families[i].queueFlags & vk::QueueFlagBits::eCompute) return i;
    throw VulkanError("the Vulkan device has no compute queue");
}

} // namespace

void ValidationLog::add(std::string message) {
    std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

std::vector<DeviceInfo> listDevices() {
    const auto loader = loadVulkan();
    const auto instance = createInstance(loader, false, nullptr);
    const auto devices = physicalDevicesOf(instance);
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
    return infos;
}

VulkanContext::VulkanContext(const ContextOptions& options)
    : submissionTimeout_(options.submissionTimeout), mostGroupsPerDispatch_(options.mostGroupsPerDispatch),
      onDeviceFailure_(options.onDeviceFailure), loader_(loadVulkan()),
      validationLog_(options.validationLog ? options.validationLog : std::make_shared<ValidationLog>()) {
    const char* validationFromEnvironment = std::getenv("IBLKIT_VALIDATION");
    const bool asked = options.validation || (validationFromEnvironment && std::string(validationFromEnvironment) == "1");
#ifdef NDEBUG
    const bool debugBuild = false;
#else
    const bool debugBuild = true; // debug builds validate whenever the layer is installed
#endif
    const bool installed = layerAvailable(loader_, kValidationLayer);
    const bool wanted = asked || (debugBuild && installed);
    if (asked && !installed)
        throw VulkanError("validation was asked for, but VK_LAYER_KHRONOS_validation is not installed "
                          "(Debian package vulkan-validationlayers)");
    validationEnabled_ = wanted;
    instance_ = createInstance(loader_, validationEnabled_, validationLog_.get());
    if (validationEnabled_) messenger_ = vk::raii::DebugUtilsMessengerEXT(instance_, messengerInfo(validationLog_.get()));

    auto devices = physicalDevicesOf(instance_);
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
    const size_t chosen = chooseDevice(infos, options.device);
    physicalDevice_ = std::move(devices[chosen]);
    deviceInfo_ = infos[chosen];

    queueFamily_ = computeQueueFamily(physicalDevice_);
    const auto family = physicalDevice_.getQueueFamilyProperties()[queueFamily_];
    canDraw_ = bool(family.queueFlags & vk::QueueFlagBits::eGraphics);
    if (family.timestampValidBits > 0) timestampPeriod_ = physicalDevice_.getProperties().limits.timestampPeriod;
    const float priority = 1.0f;
    const vk::DeviceQueueCreateInfo queueInfo({}, queueFamily_, 1, &priority);
    const bool float16Int8 = hasDeviceExtension(physicalDevice_, VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME);
    const bool descriptorIndexing = hasDeviceExtension(physicalDevice_, VK_EXT_DESCRIPTOR_INDEXING_EXTENSION_NAME);
    shaderFeatures_ = supportedShaderFeatures(physicalDevice_, float16Int8, descriptorIndexing);
    std::vector<const char*> extensions;
    if (shaderFeatures_.float16 || shaderFeatures_.int8) extensions.push_back(VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME);
    // Its dependency, VK_KHR_maintenance3, is core in Vulkan 1.1.
    if (shaderFeatures_.descriptorIndexing()) extensions.push_back(VK_EXT_DESCRIPTOR_INDEXING_EXTENSION_NAME);
    const ShaderFeatureChain features(shaderFeatures_);
    vk::DeviceCreateInfo deviceInfo({}, queueInfo, {}, extensions);
    deviceInfo.pNext = features.chain();
    device_ = vk::raii::Device(physicalDevice_, deviceInfo);
    queue_ = vk::raii::Queue(device_, queueFamily_, 0);
    commandPool_ = vk::raii::CommandPool(
        device_, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eTransient, queueFamily_));
    pipelineCache_ = vk::raii::PipelineCache(device_, vk::PipelineCacheCreateInfo());
}

uint32_t VulkanContext::memoryTypeIndex(uint32_t allowedTypes, vk::MemoryPropertyFlags properties) const {
    const auto memory = physicalDevice_.getMemoryProperties();
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((allowedTypes & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
    throw VulkanError("the Vulkan device has no memory type with the properties " + vk::to_string(properties));
}

vk::DeviceSize VulkanContext::largestHeapSize() const {
    const auto memory = physicalDevice_.getMemoryProperties();
    vk::DeviceSize largest = 0;
    for (uint32_t i = 0; i < memory.memoryHeapCount; ++i) largest = std::max(largest, memory.memoryHeaps[i].size);
    return largest;
}

void VulkanContext::submitAndWait(const std::function<void(const vk::raii::CommandBuffer&)>& record) const {
    vk::raii::CommandBuffers buffers(device_, vk::CommandBufferAllocateInfo(*commandPool_, vk::CommandBufferLevel::ePrimary, 1));
    const auto& commands = buffers.front();
    commands.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    record(commands);
    commands.end();
    vk::raii::Fence fence(device_, vk::FenceCreateInfo());
    const vk::CommandBuffer handle = *commands;
    queue_.submit(vk::SubmitInfo({}, {}, handle), *fence);
    const auto nanoseconds = uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(submissionTimeout_).count());
    vk::Result waited;
    try {
        waited = device_.waitForFences(*fence, VK_TRUE, nanoseconds);
    } catch (const vk::DeviceLostError&) {
        waited = vk::Result::eErrorDeviceLost;
    }
    if (waited == vk::Result::eSuccess) return;
    // The device may still be running the commands: freeing them, or the fence, is not allowed.
    for (auto& buffer : buffers) buffer.release();
    fence.release();
    if (waited == vk::Result::eTimeout)
        failDevice("the device did not finish a submission within " +
                   std::to_string(std::chrono::duration_cast<std::chrono::seconds>(submissionTimeout_).count()) +
                   " s: a shader that never ends, or work that needs a longer limit");
    failDevice("the Vulkan device was lost while it ran a submission (" + vk::to_string(waited) +
               "): a driver crash or a device reset");
}

void VulkanContext::failDevice(const std::string& message) const {
    if (onDeviceFailure_) onDeviceFailure_(message);
    throw VulkanError(message);
}

} // namespace iblkit::vulkan
