#include "plan_command.hpp"

#include "api/bake_settings_of.hpp"
#include "bake_options.hpp"
#include "bake_plan.hpp"
#include "environment_input.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <memory>

namespace iblkit::cli {

void addPlanCommand(CLI::App& app) {
    struct Arguments {
        BakeRequest request;
        std::string scene;
        std::string environment;
        std::string lutFormat = "rg16f";
        bool json = false;
    };
    auto arguments = std::make_shared<Arguments>();
    auto* command = app.add_subcommand("plan", "Print what a bake computes for a glTF scene's materials: the outputs, the "
                                               "specular mips, the LUT rows, the kernels, and the estimated time and error");
    command->add_option("SCENE", arguments->scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    command->add_option("ENV", arguments->environment, "The environment, as for bake (a cube input sets the size)");
    addBakeSettingOptions(*command, arguments->request, arguments->lutFormat);
    command->add_flag("--json", arguments->json, "Print the plan as JSON");
    command->callback([arguments] {
        auto request = arguments->request;
        if (!arguments->environment.empty()) request.environment = arguments->environment;
        request.lutFormat = lutFormatNamed(arguments->lutFormat);
        auto settings = bake::resolveSettings(api::bakeSettingsOf(request));
        // Read as the bake reads it, so that the plan refuses what the bake refuses (a missing,
        // unreadable or undecodable file); only a cube input has a size of its own. Its texels' NaN
        // or negative values are the bake's to judge.
        uint32_t inputCubeSize = 0;
        if (settings.environment) {
            const auto input = bake::loadEnvironment(*settings.environment, {true, false});
            if (bake::isCubeInput(*settings.environment)) inputCubeSize = input.cubeSize;
        }
        bake::resolveFaceSize(settings, inputCubeSize);
        const auto plan = bake::planBake(settings, scene::readSceneMaterials(arguments->scene));
        if (arguments->json) fmt::print("{}\n", bake::planJson(plan).dump(2));
        else fmt::print("{}", bake::planText(plan));
    });
}

} // namespace iblkit::cli
