#include "json_fields.hpp"

#include "run_error.hpp"

#include <fmt/core.h>

#include <cmath>
#include <set>

namespace iblkit::run {

using nlohmann::json;

void JsonFields::fail(const std::string& where, const std::string& why) const {
    throw RunError(file_.string() + ": error: " + where + ": " + why);
}

const json& JsonFields::object(const json& value, const std::string& where) const {
    if (!value.is_object()) fail(where, "must be an object");
    return value;
}

const json& JsonFields::objectOf(const json& value, const std::string& where, std::initializer_list<const char*> keys) const {
    object(value, where);
    const std::set<std::string> allowed(keys.begin(), keys.end());
    for (const auto& [key, member] : value.items())
        if (!allowed.count(key)) fail(where, "unknown key '" + key + "'");
    return value;
}

const json& JsonFields::array(const json& value, const std::string& where) const {
    if (!value.is_array()) fail(where, "must be an array");
    return value;
}

std::string JsonFields::text(const json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "must be a string");
    return value.get<std::string>();
}

bool JsonFields::flag(const json& value, const std::string& where) const {
    if (!value.is_boolean()) fail(where, "must be true or false");
    return value.get<bool>();
}

std::string JsonFields::oneOf(const json& value, const std::string& where, std::initializer_list<const char*> choices) const {
    const auto chosen = text(value, where);
    std::string list;
    for (const char* choice : choices) {
        if (chosen == choice) return chosen;
        list += (list.empty() ? "" : ", ") + std::string(choice);
    }
    fail(where, "unknown value '" + chosen + "' (" + list + ")");
}

double JsonFields::number(const json& value, const std::string& where) const {
    if (!value.is_number()) fail(where, "must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) fail(where, "must be finite");
    return number;
}

double JsonFields::nonNegative(const json& value, const std::string& where) const {
    const double result = number(value, where);
    if (result < 0) fail(where, fmt::format("must not be negative (it is {:g})", result));
    return result;
}

uint64_t JsonFields::whole(const json& value, const std::string& where, uint64_t least, uint64_t most) const {
    if (!value.is_number()) fail(where, "must be a whole number");
    if (value.is_number_unsigned()) {
        const auto result = value.get<uint64_t>();
        if (result < least || result > most) fail(where, fmt::format("{} is outside [{}, {}]", result, least, most));
        return result;
    }
    if (value.is_number_integer()) fail(where, fmt::format("{} is outside [{}, {}]", value.get<int64_t>(), least, most));
    const double result = value.get<double>();
    if (result != std::floor(result)) fail(where, fmt::format("{:g} is not a whole number", result));
    if (!(result >= double(least) && result <= double(most)))
        fail(where, fmt::format("{:g} is outside [{}, {}]", result, least, most));
    return uint64_t(result);
}

std::vector<double> JsonFields::numbers(const json& value, const std::string& where) const {
    if (value.is_number()) return {number(value, where)};
    if (!value.is_array()) fail(where, "must be a number or an array of numbers");
    return numberArray(value, where);
}

std::vector<double> JsonFields::numberArray(const json& value, const std::string& where) const {
    array(value, where);
    if (value.empty()) fail(where, "must not be empty");
    std::vector<double> result;
    for (size_t i = 0; i < value.size(); ++i) result.push_back(number(value[i], fmt::format("{}[{}]", where, i)));
    return result;
}

std::vector<uint64_t> JsonFields::wholeArray(const json& value, const std::string& where, size_t fewest, size_t most,
                                             uint64_t least, uint64_t largest) const {
    array(value, where);
    if (value.size() < fewest || value.size() > most)
        fail(where, fewest == most ? fmt::format("takes {} numbers", fewest) : fmt::format("takes {} to {} numbers", fewest, most));
    std::vector<uint64_t> result;
    for (size_t i = 0; i < value.size(); ++i) result.push_back(whole(value[i], fmt::format("{}[{}]", where, i), least, largest));
    return result;
}

std::vector<std::string> JsonFields::textArray(const json& value, const std::string& where) const {
    array(value, where);
    std::vector<std::string> result;
    for (size_t i = 0; i < value.size(); ++i) result.push_back(text(value[i], fmt::format("{}[{}]", where, i)));
    return result;
}

std::map<std::string, std::string> JsonFields::textMap(const json& value, const std::string& where) const {
    object(value, where);
    std::map<std::string, std::string> result;
    for (const auto& [key, member] : value.items()) {
        if (member.is_number()) result[key] = member.dump();
        else result[key] = text(member, where + "." + key);
    }
    return result;
}

} // namespace iblkit::run
