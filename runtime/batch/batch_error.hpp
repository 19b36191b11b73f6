#pragma once

#include <stdexcept>

namespace iblkit::batch {

// A batch's list, shard or records refused: one line naming the file (and line) and the problem.
class BatchError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::batch
