#pragma once

#include <cstddef>
#include <ostream>
#include <span>
#include <string_view>
#include <vector>

namespace iblkit::fuzz {

// One function per kind of input a user can feed the kit. Each takes any bytes and must end in
// a result or in the error type its loader documents (one line), never in a crash, a hang, an
// abort or another exception: what a fuzzer or the corpus replay reports is a finding.
struct Target {
    std::string_view name; // also the corpus folder under tests/fuzz/corpus/
    void (*run)(std::span<const std::byte> bytes);
};

const std::vector<Target>& targets();

// For test names and messages: the target's name.
inline void PrintTo(const Target& target, std::ostream* out) { *out << target.name; }

} // namespace iblkit::fuzz
