#include "frontend_refusals.hpp"

#include <array>
#include <regex>

namespace iblkit::compiler {
namespace {

constexpr char kFrontend[] = "glslang's HLSL frontend";

// glslang names an object's methods __BI_Name.
std::string methodOrFunction(const std::string& name) {
    if (name.rfind("__BI_", 0) == 0) return "the method '" + name.substr(5) + "'";
    return "'" + name + "'";
}

struct Rewording {
    std::regex pattern;
    std::string (*words)(const std::smatch& match);
};

const std::array<Rewording, 14>& rewordings() {
    static const std::array<Rewording, 14> kRewordings{{
        {std::regex(R"('(\w+)' : no matching overloaded function found)"),
         [](const std::smatch& m) {
             return "a call to " + methodOrFunction(m[1]) + " whose arguments match none of its declarations as " + kFrontend +
                    " converts them (it converts less than DXC: nothing to a 16-bit float, no vector to a shorter one, no sparse-"
                    "feedback status): convert the arguments to the parameters' types";
         }},
        {std::regex(R"('(\w+)' : ambiguous best function under implicit type conversion)"),
         [](const std::smatch& m) {
             return "a call to " + methodOrFunction(m[1]) + " that several of its declarations could take once " + kFrontend +
                    " converts the arguments (a vector longer than the parameter): convert them to the declaration's types";
         }},
        {std::regex(R"('return' : type does not match, or is not convertible to, the function's return type)"),
         [](const std::smatch&) {
             return std::string("a return value ") + kFrontend + " does not convert to the function's return type (a 32-bit value "
                    "to a 16-bit one, a struct to another struct): convert it, as in return (half3)value;";
         }},
        {std::regex(R"(cannot convert from '\s*(.+?)' to '\s*(.+?)')"),
         [](const std::smatch& m) {
             return "an implicit conversion from " + std::string(m[1]) + " to " + std::string(m[2]) + ", which " + kFrontend +
                    " does not make: write it as a cast";
         }},
        {std::regex(R"('constructor' : can't convert|cannot construct with these arguments)"),
         [](const std::smatch&) {
             return std::string("a constructor or cast whose arguments ") + kFrontend + " does not convert to its type (an integer "
                    "or a 32-bit value to a 16-bit float): convert each argument to the type's scalar first";
         }},
        {std::regex(R"('structure' : Expected)"),
         [](const std::smatch&) {
             return std::string("a member or method of something ") + kFrontend + " does not hold as an object: an element of an "
                    "array of ByteAddressBuffer or StructuredBuffer (Buffers[i].Load(...)), which it cannot index: declare each "
                    "buffer on its own register";
         }},
        {std::regex(R"('([^\w\s]+)' : Expected)"),
         [](const std::smatch& m) { return "a syntax error: '" + std::string(m[1]) + "' expected here"; }},
        {std::regex(R"('(.+?)' : Expected)"),
         [](const std::smatch& m) {
             return "code " + std::string(kFrontend) + " cannot parse here (it expected a " + std::string(m[1]) +
                    "): a construct it does not implement, such as a template or a type it lacks (docs/compiler.md lists them)";
         }},
        {std::regex(R"('(\w+)' : no such field in structure)"),
         [](const std::smatch& m) { return "'" + std::string(m[1]) + "' is not a member of the struct it is read from"; }},
        {std::regex(R"('(\w+)' : (?:undeclared identifier|unknown variable))"),
         [](const std::smatch& m) { return "'" + std::string(m[1]) + "' is not declared where it is used"; }},
        {std::regex(R"('basic type in texture' : Unimplemented)"),
         [](const std::smatch&) {
             return std::string("a texture or typed buffer whose element type ") + kFrontend +
                    " does not take (a struct, or a 16-bit type): declare it of a 32-bit scalar or vector and convert "
                    "what it reads";
         }},
        {std::regex(R"(left of '\[' is not of type array, matrix, or vector)"),
         [](const std::smatch&) {
             return std::string("an index into something ") + kFrontend + " does not hold as an array (an element of an array of "
                    "buffers, or a resource taken from a struct): index the global resource itself";
         }},
        {std::regex(R"(buffer aliasing not yet supported)"),
         [](const std::smatch&) {
             return std::string("a local variable or struct member holding a buffer, whose value the kit could not put in its "
                    "place (what selects the buffer changes before it is used): index the global buffer where it is used");
         }},
        {std::regex(R"(unimplemented: (.+))"),
         [](const std::smatch& m) { return std::string("a construct ") + kFrontend + " does not implement: " + std::string(m[1]); }},
    }};
    return kRewordings;
}

struct SpirvRewording {
    const char* pattern;
    const char* words;
};

constexpr SpirvRewording kSpirvRewordings[] = {
    {"OpTypeRuntimeArray must have storage class",
     "a buffer held in a struct or a local (a StructuredBuffer or ByteAddressBuffer member, or a struct of resources passed "
     "to a function), which glslang copies where Vulkan cannot hold it: pass or index the global buffer itself"},
    {"OpTypeStruct must not contain an opaque type",
     "a struct holding textures or samplers that glslang could not take apart: pass the resources themselves"},
    {"conflicting input location assignment|conflicting output location assignment",
     "two varyings at one location (a system value glslang does not know, or an array member of a hull, domain or geometry "
     "shader's varying, which glslang splits wrongly): hold the array in vectors of its own"},
    {"Invalid storage class for pointer operand",
     "a buffer passed to a function glslang could not inline: index the global buffer inside the function"},
    {"Image Operand Offset can only be used with OpImage",
     "a texture offset that is not a constant: Vulkan takes a run-time offset only in a Gather: make the offset a constant"},
};

} // namespace

std::string invalidSpirvInKitWords(const std::string& error) {
    const size_t message = error.find(": error: ");
    if (message == std::string::npos) return error;
    const std::string validator = error.substr(message + 9);
    if (validator.rfind("the SPIR-V is not valid", 0) != 0) return error; // worded by the kit already
    for (const auto& rewording : kSpirvRewordings)
        if (std::regex_search(validator, std::regex(rewording.pattern)))
            return error.substr(0, message) + ": error: " + rewording.words + " (" + validator + ")";
    return error.substr(0, message) + ": error: glslang wrote SPIR-V for this shader that Vulkan does not accept (" + validator + ")";
}

std::string inKitWords(const std::string& error) {
    static const std::regex located(R"(^((?:[^\n]*\n)*?[^\n]*?: error: )(.*)$)");
    std::smatch parts;
    if (!std::regex_match(error, parts, located)) return error;
    const std::string place = parts[1];
    const std::string message = parts[2];
    for (const auto& rewording : rewordings()) {
        std::smatch match;
        if (std::regex_search(message, match, rewording.pattern))
            return place + rewording.words(match) + " (glslang: " + message + ")";
    }
    return place + "code " + kFrontend + " refuses (glslang: " + message + ")";
}

} // namespace iblkit::compiler
