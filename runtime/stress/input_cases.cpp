#include "input_cases.hpp"

#include "bake_error.hpp"
#include "environment_input.hpp"
#include "image_error.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <limits>
#include <unistd.h>

namespace iblkit::stress {
namespace {

namespace fs = std::filesystem;

struct Case {
    const char* input;
    float value; // at texel (5, 7), green channel
    bake::InputPolicy policy;
    const char* policyName;
    bool refused;
};

fs::path writePanorama(const fs::path& folder, float value) {
    image_io::FloatImage image{64, 32, 3, std::vector<float>(64 * 32 * 3, 1.f)};
    image.values[(7 * 64 + 5) * 3 + 1] = value;
    const auto path = folder / "panorama.exr";
    image_io::writeExr(path, image);
    return path;
}

std::string outcomeOf(const bake::EnvironmentInput& input) {
    if (input.sanitizedTexels) return fmt::format("baked: {} NaN/Inf texels set to 0", input.sanitizedTexels);
    if (input.negative.count)
        return fmt::format("baked: {} negative texels clamped to 0, the most negative {:g}", input.negative.count,
                           input.negative.mostNegative);
    return "baked unchanged";
}

InputRow check(const fs::path& folder, const Case& each) {
    InputRow row{each.input, each.policyName, {}, false, each.refused};
    const auto path = writePanorama(folder, each.value);
    try {
        row.outcome = outcomeOf(bake::loadEnvironment(path, each.policy));
    } catch (const std::exception& error) { // BakeError, image_io::ImageError: one line each
        row.refused = true;
        row.outcome = error.what();
        const auto at = row.outcome.find(path.string());
        if (at != std::string::npos) row.outcome.replace(at, path.string().size(), "panorama.exr");
    }
    return row;
}

} // namespace

std::vector<InputRow> checkInputPolicies() {
    const float infinity = std::numeric_limits<float>::infinity();
    const Case cases[] = {
        {"a texel of 1e37", 1e37f, {}, "default", true},
        {"a texel of 1e37", 1e37f, {true, false}, "--sanitize", true},
        {"a texel of 1e19", 1e19f, {}, "default", false},
        {"a NaN texel", std::numeric_limits<float>::quiet_NaN(), {}, "default", true},
        {"a NaN texel", std::numeric_limits<float>::quiet_NaN(), {true, false}, "--sanitize", false},
        {"a +Inf texel", infinity, {}, "default", true},
        {"a -Inf texel", -infinity, {}, "default", true},
        {"a texel of -7.5e-4", -7.5e-4f, {}, "default", false},
        {"a texel of -7.5e-4", -7.5e-4f, {false, true}, "--strict", true},
    };
    const auto folder = fs::temp_directory_path() / fmt::format("iblkit-stress-{}", getpid());
    fs::create_directories(folder);
    std::vector<InputRow> rows;
    for (const auto& each : cases) rows.push_back(check(folder, each));
    fs::remove_all(folder);
    return rows;
}

} // namespace iblkit::stress
