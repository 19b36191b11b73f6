// The libFuzzer program (fuzz preset): `iblkit_fuzz --target=NAME [libFuzzer flags] CORPUS...`
// runs one of the targets of fuzz_targets.cpp. libFuzzer ignores flags that start with "--" and
// hands them on to the processes it forks, so every process picks the same target.
#include "fuzz_targets.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

const iblkit::fuzz::Target* chosenTarget = nullptr;

const iblkit::fuzz::Target* targetNamed(std::string_view name) {
    for (const auto& target : iblkit::fuzz::targets())
        if (target.name == name) return &target;
    return nullptr;
}

[[noreturn]] void refuse(std::string_view problem) {
    std::string names;
    for (const auto& target : iblkit::fuzz::targets()) names += " " + std::string(target.name);
    std::fprintf(stderr, "iblkit_fuzz: %.*s; give --target= one of:%s\n", int(problem.size()), problem.data(),
                 names.c_str());
    std::exit(2);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    constexpr std::string_view flag = "--target=";
    for (int i = 1; i < *argc; ++i) {
        const std::string_view argument = (*argv)[i];
        if (argument.starts_with(flag)) chosenTarget = targetNamed(argument.substr(flag.size()));
        if (argument.starts_with(flag) && !chosenTarget) refuse("unknown target '" + std::string(argument.substr(flag.size())) + "'");
    }
    if (!chosenTarget) refuse("no target");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    chosenTarget->run({reinterpret_cast<const std::byte*>(data), size});
    return 0;
}
