#pragma once

#include "compiler.hpp"
#include "vulkan_context.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <optional>

namespace iblkit::testing {

// A validated Vulkan context per test on the default device (lavapipe). Anything the
// validation layer says — during the test or while the context is destroyed, which is where
// leaked objects are reported — fails the test.
class VulkanTest : public ::testing::Test {
protected:
    void SetUp() override {
        vulkan::ContextOptions options;
        options.validation = true;
        options.validationLog = log_;
        context_.emplace(options);
    }
    void TearDown() override {
        context_.reset();
        for (const auto& message : log_->messages()) ADD_FAILURE() << "validation: " << message;
    }
    const vulkan::VulkanContext& context() const { return *context_; }

private:
    std::shared_ptr<vulkan::ValidationLog> log_ = std::make_shared<vulkan::ValidationLog>();
    std::optional<vulkan::VulkanContext> context_;
};

compiler::CompiledShader compileTestShader(const std::string& name, const std::string& source,
                                           std::map<std::string, std::string> imageFormats = {});

} // namespace iblkit::testing
