#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

namespace iblkit::run {

// Typed reads of a run file's JSON values. Each refuses a value of the wrong type or out of
// range with RunError("<file>: error: <key>: <why>"), before anything narrows it: a count of
// 2^32 is refused, not cut to 0.
class JsonFields {
public:
    explicit JsonFields(std::filesystem::path file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& where, const std::string& why) const;

    const nlohmann::json& object(const nlohmann::json& value, const std::string& where) const;
    // An object holding only `keys`.
    const nlohmann::json& objectOf(const nlohmann::json& value, const std::string& where,
                                   std::initializer_list<const char*> keys) const;
    const nlohmann::json& array(const nlohmann::json& value, const std::string& where) const;
    std::string text(const nlohmann::json& value, const std::string& where) const;
    bool flag(const nlohmann::json& value, const std::string& where) const;
    std::string oneOf(const nlohmann::json& value, const std::string& where, std::initializer_list<const char*> choices) const;
    double number(const nlohmann::json& value, const std::string& where) const; // finite
    double nonNegative(const nlohmann::json& value, const std::string& where) const;
    uint64_t whole(const nlohmann::json& value, const std::string& where, uint64_t least, uint64_t most) const;
    // A number, or a non-empty array of them.
    std::vector<double> numbers(const nlohmann::json& value, const std::string& where) const;
    // A non-empty array of numbers.
    std::vector<double> numberArray(const nlohmann::json& value, const std::string& where) const;
    // An array of `fewest` to `most` whole numbers, each in [least, largest].
    std::vector<uint64_t> wholeArray(const nlohmann::json& value, const std::string& where, size_t fewest, size_t most,
                                     uint64_t least, uint64_t largest) const;
    std::vector<std::string> textArray(const nlohmann::json& value, const std::string& where) const;
    // An object of strings (numbers are taken as written: {"SAMPLE_COUNT": 1024}).
    std::map<std::string, std::string> textMap(const nlohmann::json& value, const std::string& where) const;

private:
    std::filesystem::path file_;
};

} // namespace iblkit::run
