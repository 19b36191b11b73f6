#pragma once

#include <stdexcept>

namespace iblkit::bench {

// A bench that cannot run as asked: one line naming the problem.
class BenchError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::bench
