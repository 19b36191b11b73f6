#include "bake_plan.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

namespace iblkit::bake {
namespace {

nlohmann::json optionalJson(const std::optional<double>& value) { return value ? nlohmann::json(*value) : nlohmann::json(); }

nlohmann::json estimateJson(const Estimate& estimate) {
    return {{"device_ms", optionalJson(estimate.deviceMs)},
            {"error_rms", optionalJson(estimate.errorRms)},
            {"error_max", optionalJson(estimate.errorMax)}};
}

std::string optionalText(const std::optional<double>& value, const char* format) {
    return value ? fmt::format(fmt::runtime(format), *value) : "-";
}

// "needed, 34 ms on the device, error max 1.6e-05", or "skipped".
std::string stepText(bool needed, const Estimate& estimate) {
    if (!needed) return "skipped";
    return fmt::format("needed, {} ms on the device, error rms {} max {}", optionalText(estimate.deviceMs, "{:.0f}"),
                       optionalText(estimate.errorRms, "{:.2e}"), optionalText(estimate.errorMax, "{:.2e}"));
}

} // namespace

nlohmann::json planJson(const BakePlan& plan) {
    nlohmann::json mips = nlohmann::json::array();
    for (const auto& mip : plan.mips)
        mips.push_back({{"mip", mip.mip}, {"roughness", mip.roughness}, {"face_size", mip.faceSize},
                        {"needed", mip.needed}, {"estimate", estimateJson(mip.estimate)}});
    nlohmann::json json = {
        {"scene", plan.scene ? nlohmann::json(plan.scene->string()) : nlohmann::json()},
        {"roughness", plan.roughness.empty() ? nlohmann::json() : nlohmann::json({plan.roughness.min, plan.roughness.max})},
        {"outputs", {{"specular", plan.specular}, {"irradiance", plan.irradiance}, {"brdf_lut", plan.lut}}},
        {"recipe", plan.recipe ? nlohmann::json(plan.recipe->name) : nlohmann::json()},
        {"specular_mips", mips},
        {"brdf_lut_rows", plan.lut ? nlohmann::json({plan.lutFirstRow, plan.lutLastRow}) : nlohmann::json()},
        {"kernels", plan.kernels},
        {"estimates", {{"specular", estimateJson(plan.specularEstimate)},
                       {"brdf_lut", estimateJson(plan.lutEstimate)},
                       {"irradiance", estimateJson(plan.irradianceEstimate)}}},
        {"reasons", plan.reasons},
        {"unknown_extensions", plan.unknownExtensions},
        {"notes", plan.notes}};
    return json;
}

std::string planText(const BakePlan& plan) {
    std::string text;
    if (plan.scene) text += fmt::format("scene       {}\n", plan.scene->string());
    for (const auto& reason : plan.reasons) text += fmt::format("            {}\n", reason);
    text += plan.roughness.empty() ? "roughness   none lit\n"
                                   : fmt::format("roughness   {:.3f} to {:.3f}\n", plan.roughness.min, plan.roughness.max);
    if (plan.recipe)
        text += fmt::format("recipe      {} ({} lobe, {} lods{})\n", plan.recipe->name, shading::nameOf(plan.recipe->weighting),
                            shading::nameOf(plan.recipe->mapping),
                            plan.recipe->lights ? ", bright sources taken out as lights" : "");
    text += fmt::format("specular    {}\n", stepText(plan.specular, plan.specularEstimate));
    text += "            mip  size  roughness  needed   device ms  error rms  error max\n";
    for (const auto& mip : plan.mips)
        text += fmt::format("            {:>3}  {:>4}  {:>9.3f}  {:<7}  {:>9}  {:>9}  {:>9}\n", mip.mip, mip.faceSize,
                            mip.roughness, mip.needed ? "yes" : "no", optionalText(mip.estimate.deviceMs, "{:.1f}"),
                            optionalText(mip.estimate.errorRms, "{:.2e}"), optionalText(mip.estimate.errorMax, "{:.2e}"));
    text += fmt::format("brdf lut    {}{}\n", stepText(plan.lut, plan.lutEstimate),
                        plan.lut ? fmt::format("; rows {} to {} are read", plan.lutFirstRow, plan.lutLastRow) : "");
    text += fmt::format("irradiance  {}\n", stepText(plan.irradiance, plan.irradianceEstimate));
    text += "kernels    ";
    for (const auto& kernel : plan.kernels) text += " " + kernel + ";";
    text += "\n";
    for (const auto& extension : plan.unknownExtensions)
        text += fmt::format("warning     the scene uses {}, which the kit does not understand\n", extension);
    for (const auto& note : plan.notes) text += fmt::format("note        {}\n", note);
    return text;
}

} // namespace iblkit::bake
