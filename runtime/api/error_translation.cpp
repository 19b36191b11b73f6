#include "api/error_translation.hpp"

#include "compile_error.hpp"
#include "lowering_error.hpp"
#include "vulkan_error.hpp"

#include <new>

namespace iblkit::api {

void rethrowAs(ErrorKind kind) {
    try {
        throw;
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const compiler::CompileError& error) {
        throw Error(ErrorKind::CompileFailed, error.what());
    } catch (const lowering::LoweringError& error) {
        throw Error(ErrorKind::CompileFailed, error.what());
    } catch (const vulkan::VulkanError& error) {
        throw Error(ErrorKind::DeviceFailed, error.what());
    } catch (const std::exception& error) {
        throw Error(kind, error.what());
    }
}

} // namespace iblkit::api
