#pragma once

#include <iblkit/error.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>

namespace iblkit::testing {

// The kind and message of the Error `call` throws; a failure of the test when it throws none.
inline std::pair<ErrorKind, std::string> errorOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const Error& error) {
        return {error.kind(), error.what()};
    }
    ADD_FAILURE() << "no error";
    return {ErrorKind::BakeFailed, ""};
}

} // namespace iblkit::testing
