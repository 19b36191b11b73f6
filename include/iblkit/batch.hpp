#pragma once

#include <iblkit/bake.hpp>
#include <iblkit/error.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace iblkit {

// One bake of a batch: its request, and its folder's name under the batch's folder.
struct BatchBake {
    std::string name; // one path component: letters, digits, '.', '_' and '-', not starting with '.'
    BakeRequest request;
};

struct BatchResult {
    std::string name;
    std::optional<BakeSummary> summary; // the bake's, when it succeeded
    std::optional<Error> error;         // why it failed, when it did
    double wallMilliseconds = 0;        // from its start to its files committed, or to its failure
};

struct BatchOptions {
    // Called on the calling thread as each bake starts and ends, in the order of the list.
    std::function<void(const BatchBake&)> onStart;
    std::function<void(const BatchResult&)> onResult;
};

// Bakes each request into FOLDER/NAME as bakeToFolder(request, FOLDER/NAME) does, byte for byte,
// in one process: one device, each kernel made once, one LUT per set of LUT settings. While the
// device computes one bake, the next one's input is read and decoded and the last one's files are
// written. A bake that fails is reported and the rest go on. Every request must choose the same
// device and validation (they share one device). Throws Error (BadInput) before any work for a
// name that is not one path component, a name given twice, or requests of different devices.
std::vector<BatchResult> bakeBatch(const std::vector<BatchBake>& bakes, const std::filesystem::path& folder,
                                   const BatchOptions& options = {});

} // namespace iblkit
