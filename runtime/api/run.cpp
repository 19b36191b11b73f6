#include <iblkit/run.hpp>

#include "api/error_translation.hpp"
#include "api/report_stream.hpp"

#include "run_executor.hpp"
#include "run_file.hpp"

namespace iblkit {

RunResult executeRunFile(const RunRequest& request) {
    const auto spec = api::translated(ErrorKind::BadInput, [&] { return run::readRunFile(request.runFile); });
    const auto api = request.api == RunApi::OpenGl ? run::RunApi::OpenGl : request.api == RunApi::All ? run::RunApi::All : run::RunApi::Vulkan;
    const run::RunOptions options{api, request.device, request.validation, request.timeout, request.onDeviceFailure};
    api::ReportBuffer report(request.reportStream);
    std::ostream out(&report);
    const bool passed = api::translated(ErrorKind::RunFailed, [&] { return run::executeRun(spec, options, out); });
    out.flush();
    return {passed, report.text()};
}

} // namespace iblkit
