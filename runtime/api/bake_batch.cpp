#include <iblkit/batch.hpp>

#include "api/bake_settings_of.hpp"
#include "api/folder_bake_job.hpp"

#include "bake_session.hpp"
#include "batch_list.hpp"

#include <fmt/format.h>

#include <chrono>
#include <future>
#include <set>

namespace iblkit {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void requireBatch(const std::vector<BatchBake>& bakes) {
    std::set<std::string> names;
    for (const auto& bake : bakes) {
        if (!batch::isFolderName(bake.name))
            throw Error(ErrorKind::BadInput, fmt::format("batch: '{}' is not a folder name (letters, digits, '.', '_' and "
                                                         "'-', not starting with '.')", bake.name));
        if (!names.insert(bake.name).second)
            throw Error(ErrorKind::BadInput, fmt::format("batch: '{}' is named twice", bake.name));
        const auto& first = bakes.front().request;
        if (bake.request.device != first.device || bake.request.validation != first.validation)
            throw Error(ErrorKind::BadInput, fmt::format("batch: '{}' chooses another device or validation than '{}': a "
                                                         "batch runs on one device", bake.name, bakes.front().name));
    }
}

// A bake in flight: its job, its start, and the error that ended it.
struct Flight {
    const BatchBake* bake;
    api::FolderBakeJob job;
    Clock::time_point started = Clock::now();
    std::optional<Error> error;
};

template <typename Step>
void attempt(Flight& flight, Step&& step) {
    if (flight.error) return;
    try {
        step();
    } catch (const Error& error) {
        flight.error = error;
    } catch (const std::bad_alloc&) {
        flight.error = Error(ErrorKind::BakeFailed, "out of memory");
    }
}

// Above this face size a bake's images are hundreds of megabytes: the bakes run one after the
// other instead of three at once (the next's input, this one's maps, the last one's files).
constexpr uint32_t kLargestOverlappedSize = 1024;

bool overlaps(const BatchBake& bake) {
    const auto& request = bake.request;
    if (request.size) return *request.size <= kLargestOverlappedSize;
    if (!request.environment) return true; // the built-in sky, at the default 256²
    // A cube's faces are its own size, not known until it is read.
    std::error_code error;
    const auto extension = request.environment->extension();
    return extension != ".ktx2" && extension != ".dds" && !std::filesystem::is_directory(*request.environment, error);
}

class BatchRun {
public:
    BatchRun(const std::vector<BatchBake>& bakes, const std::filesystem::path& folder, const BatchOptions& options)
        : bakes_(bakes), folder_(folder), options_(options), log_(std::make_shared<vulkan::ValidationLog>()) {
        auto contextOptions = api::bakeSettingsOf(bakes.front().request).context;
        contextOptions.validationLog = log_;
        session_.emplace(contextOptions);
    }

    std::vector<BatchResult> run() {
        std::future<std::unique_ptr<Flight>> next = prepared(0);
        std::future<BatchResult> writing;
        for (size_t index = 0; index < bakes_.size(); ++index) {
            auto flight = next.get();
            const bool ahead = index + 1 < bakes_.size() && overlaps(*flight->bake) && overlaps(bakes_[index + 1]);
            if (ahead) next = prepared(index + 1);
            attempt(*flight, [&] { flight->job.compute(); });
            finish(writing);
            writing = written(std::move(flight));
            if (!ahead) finish(writing);
            if (!ahead && index + 1 < bakes_.size()) next = prepared(index + 1);
        }
        finish(writing);
        return std::move(results_);
    }

private:
    // Prepared on a thread: the session is only named, not used, there (bake.hpp).
    std::future<std::unique_ptr<Flight>> prepared(size_t index) {
        const auto& bake = bakes_[index];
        if (options_.onStart) options_.onStart(bake);
        return std::async(std::launch::async, [this, &bake] {
            auto job = api::FolderBakeJob(bake.request, folder_ / bake.name, log_);
            auto flight = std::make_unique<Flight>(Flight{&bake, std::move(job), Clock::now(), std::nullopt});
            attempt(*flight, [&] { flight->job.prepare(&*session_); });
            return flight;
        });
    }

    std::future<BatchResult> written(std::unique_ptr<Flight> flight) {
        return std::async(std::launch::async, [flight = std::move(flight)] {
            BatchResult result{flight->bake->name, {}, {}, 0};
            attempt(*flight, [&] { result.summary = flight->job.write(); });
            result.error = flight->error;
            result.wallMilliseconds = millisecondsSince(flight->started);
            return result;
        });
    }

    void finish(std::future<BatchResult>& writing) {
        if (!writing.valid()) return;
        results_.push_back(writing.get());
        // The validation layer's messages since the last result: the bakes share one device, one at a time.
        const auto messages = log_->messages();
        if (results_.back().summary)
            results_.back().summary->validationMessages.assign(messages.begin() + long(reported_), messages.end());
        reported_ = messages.size();
        if (options_.onResult) options_.onResult(results_.back());
    }

    const std::vector<BatchBake>& bakes_;
    std::filesystem::path folder_;
    const BatchOptions& options_;
    std::shared_ptr<vulkan::ValidationLog> log_;
    std::optional<bake::BakeSession> session_;
    std::vector<BatchResult> results_;
    size_t reported_ = 0; // the log's messages given to a result
};

} // namespace

std::vector<BatchResult> bakeBatch(const std::vector<BatchBake>& bakes, const std::filesystem::path& folder,
                                   const BatchOptions& options) {
    if (bakes.empty()) return {};
    requireBatch(bakes);
    return BatchRun(bakes, folder, options).run();
}

} // namespace iblkit
