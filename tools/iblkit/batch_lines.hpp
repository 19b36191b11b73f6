#pragma once

#include "batch_list.hpp"

#include <iblkit/bake.hpp>

#include <string>
#include <vector>

namespace iblkit::cli {

// A line of a batch list as the request of one bake, its flags parsed as `iblkit bake` parses
// them and its settings and input files checked, so that a bad line is refused before any work.
struct BatchLineRequest {
    batch::BatchLine line;
    BakeRequest request;
};

// Throws batch::BatchError "LIST:LINE: error: ..." for the first bad line.
std::vector<BatchLineRequest> batchLineRequests(const std::vector<batch::BatchLine>& lines, const std::string& listName);

} // namespace iblkit::cli
