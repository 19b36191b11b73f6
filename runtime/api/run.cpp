#include <iblkit/run.hpp>

#include "api/error_translation.hpp"
#include "api/report_stream.hpp"

#include "run_executor.hpp"
#include "run_file.hpp"

namespace iblkit {

RunResult executeRunFile(const RunRequest& request) {
    const auto spec = api::translated(ErrorKind::BadInput, [&] { return run::readRunFile(request.runFile); });
    const run::RunOptions options{request.device, request.validation, request.timeout, request.onDeviceFailure};
    api::ReportBuffer report(request.reportStream);
    std::ostream out(&report);
    const bool passed = api::translated(ErrorKind::RunFailed, [&] { return run::executeRun(spec, options, out); });
    out.flush();
    return {passed, report.text()};
}

} // namespace iblkit
