#include <iblkit/error.hpp>

namespace iblkit {

std::string_view errorKindName(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::BadInput: return "bad input";
    case ErrorKind::CompileFailed: return "compile failed";
    case ErrorKind::RunFailed: return "run failed";
    case ErrorKind::BakeFailed: return "bake failed";
    case ErrorKind::DeviceFailed: return "device failed";
    }
    return "unknown";
}

Error::Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}

Error::~Error() = default;

} // namespace iblkit
