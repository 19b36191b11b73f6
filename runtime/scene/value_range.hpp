#pragma once

#include <algorithm>

namespace iblkit::scene {

// A closed interval [min, max] of values a scene uses; empty until a value is included.
struct ValueRange {
    double min = 1;
    double max = 0;

    static ValueRange of(double low, double high) { return {low, high}; }
    bool empty() const { return min > max; }
    void include(double value) {
        min = std::min(min, value);
        max = std::max(max, value);
    }
    void include(const ValueRange& other) {
        if (other.empty()) return;
        include(other.min);
        include(other.max);
    }
    bool operator==(const ValueRange&) const = default;
};

} // namespace iblkit::scene
