#include "api/bake_settings_of.hpp"

namespace iblkit::api {

bake::BakeSettings bakeSettingsOf(const BakeRequest& request) {
    bake::BakeSettings settings;
    settings.environment = request.environment;
    settings.scene = request.scene;
    settings.cache = request.cache;
    settings.size = request.size;
    settings.mips = request.mips;
    settings.specularMethod = request.method;
    settings.samples = request.samples;
    settings.recipe = request.recipe;
    settings.profile = request.profile;
    settings.lutSize = request.lutSize;
    settings.lutMethod = request.lutMethod;
    settings.lutSamples = request.lutSamples;
    settings.lutFormat = request.lutFormat == LutFormat::Rg32Float ? bake::LutFormat::Rg32Float : bake::LutFormat::Rg16Float;
    settings.irradianceSize = request.irradianceSize;
    settings.dds = request.dds;
    settings.exr = request.exr;
    settings.sanitize = request.sanitize;
    settings.strict = request.strict;
    settings.context.device = request.device;
    settings.context.validation = request.validation;
    return settings;
}

} // namespace iblkit::api
