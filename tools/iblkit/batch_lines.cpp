#include "batch_lines.hpp"

#include "bake_options.hpp"
#include "batch_error.hpp"

#include "bake_settings.hpp"
#include "api/bake_settings_of.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <set>

namespace iblkit::cli {
namespace {

// The flags of the whole batch process: one output folder, cache and device for every line.
const std::set<std::string>& batchFlags() {
    static const std::set<std::string> flags{"-o", "--output", "--cache", "--no-cache", "--device", "--validate",
                                             "-q", "--quiet", "--json", "--shard", "--shards"};
    return flags;
}

void requireLineFlags(const batch::BatchLine& line) {
    for (const auto& word : line.arguments)
        if (const auto flag = word.substr(0, word.find('=')); batchFlags().count(flag))
            throw std::invalid_argument(fmt::format("{} is a flag of the batch, not of a line (give it to iblkit batch)", flag));
}

void requireInput(const char* what, const std::optional<std::filesystem::path>& path) {
    std::error_code error;
    if (path && !std::filesystem::exists(*path, error))
        throw std::invalid_argument(fmt::format("{} {}: no such file or folder", what, path->string()));
}

BakeRequest requestOf(const batch::BatchLine& line) {
    requireLineFlags(line);
    CLI::App app{"a line of a batch list"};
    app.set_help_flag();
    BakeLineArguments arguments;
    addBakeLineOptions(app, arguments);
    std::vector<std::string> words(line.arguments.rbegin(), line.arguments.rend()); // CLI11 takes them last first
    try {
        app.parse(words);
    } catch (const CLI::ParseError& error) {
        throw std::invalid_argument(error.what());
    }
    auto request = arguments.resolved();
    bake::resolveSettings(api::bakeSettingsOf(request)); // every setting checked, as the bake will
    requireInput("ENV", request.environment);
    requireInput("--scene", request.scene);
    return request;
}

} // namespace

std::vector<BatchLineRequest> batchLineRequests(const std::vector<batch::BatchLine>& lines, const std::string& listName) {
    std::vector<BatchLineRequest> requests;
    for (const auto& line : lines) {
        try {
            requests.push_back({line, requestOf(line)});
        } catch (const std::exception& error) {
            throw batch::BatchError(fmt::format("{}:{}: error: {}", listName, line.number, error.what()));
        }
    }
    return requests;
}

} // namespace iblkit::cli
