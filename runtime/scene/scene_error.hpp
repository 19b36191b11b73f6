#pragma once

#include <stdexcept>

namespace iblkit::scene {

// A scene that cannot be read: "<file>: error: <what>".
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace iblkit::scene
