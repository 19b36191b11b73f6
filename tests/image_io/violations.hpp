#pragma once

#include <string>
#include <utility>
#include <vector>

namespace iblkit::testing {

// The rules of a format a file breaks, each named with what the file holds.
class Violations {
public:
    void expect(bool holds, const std::string& rule) {
        if (!holds) list_.push_back(rule);
    }
    std::vector<std::string> take() { return std::move(list_); }

private:
    std::vector<std::string> list_;
};

} // namespace iblkit::testing
