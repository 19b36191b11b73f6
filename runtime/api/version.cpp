#include <iblkit/version.hpp>

namespace iblkit {

std::string version() { return IBLKIT_VERSION; }

} // namespace iblkit
