#include "shading/mip_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace iblkit::shading {
namespace {

constexpr double kBabylonScale = 0.8;

// Logarithmic's lod = slope log2(α size) + offset, through (c / size, 1) and (1, last).
struct LogLine {
    double slope, offset;
};

// A chain of fewer than three mips, or a face no larger than c, has no line: it maps linearly.
bool hasLogLine(const MipSchedule& schedule) { return schedule.mips >= 3 && double(schedule.size) > schedule.parameter; }

LogLine logLine(const MipSchedule& schedule) {
    const double last = double(schedule.mips) - 1, size = double(schedule.size);
    const double slope = (last - 1) / std::log2(size / schedule.parameter);
    return {slope, last - slope * std::log2(size)};
}

} // namespace

std::string_view nameOf(LodMapping mapping) {
    switch (mapping) {
    case LodMapping::Linear: return "linear";
    case LodMapping::Quadratic: return "quadratic";
    case LodMapping::Power: return "power";
    case LodMapping::Babylon: return "babylon";
    case LodMapping::Logarithmic: return "logarithmic";
    }
    return "linear";
}

LodMapping lodMappingNamed(std::string_view name) {
    for (const auto mapping :
         {LodMapping::Linear, LodMapping::Quadratic, LodMapping::Power, LodMapping::Babylon, LodMapping::Logarithmic})
        if (name == nameOf(mapping)) return mapping;
    throw std::invalid_argument("no lod mapping '" + std::string(name) +
                                "': linear, quadratic, power, babylon or logarithmic");
}

double MipSchedule::lodOf(double roughness) const {
    const double last = double(mips) - 1;
    const double r = std::clamp(roughness, 0.0, 1.0);
    switch (mapping) {
    case LodMapping::Linear: return r * last;
    case LodMapping::Quadratic: return r * (2 - r) * last;
    case LodMapping::Power: return std::pow(r, parameter) * last;
    case LodMapping::Babylon:
        return r > 0 ? std::clamp(kBabylonScale * std::log2(r * r * double(size)), 0.0, last) : 0.0;
    case LodMapping::Logarithmic: {
        if (!hasLogLine(*this)) return r * last;
        const auto line = logLine(*this);
        return r > 0 ? std::clamp(line.slope * std::log2(r * r * double(size)) + line.offset, 0.0, last) : 0.0;
    }
    }
    return 0;
}

double MipSchedule::roughnessOf(uint32_t mip) const {
    if (mip == 0 || mips < 2) return 0;
    const double t = double(mip) / (double(mips) - 1);
    switch (mapping) {
    case LodMapping::Linear: return t;
    case LodMapping::Quadratic: return 1 - std::sqrt(1 - t);
    case LodMapping::Power: return std::pow(t, 1 / parameter);
    case LodMapping::Babylon:
        return std::min(std::sqrt(std::exp2(double(mip) / kBabylonScale) / double(size)), 1.0);
    case LodMapping::Logarithmic: {
        if (!hasLogLine(*this)) return t;
        const auto line = logLine(*this);
        return std::min(std::sqrt(std::exp2((double(mip) - line.offset) / line.slope) / double(size)), 1.0);
    }
    }
    return t;
}

} // namespace iblkit::shading
