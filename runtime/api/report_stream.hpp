#pragma once

#include <ostream>
#include <streambuf>
#include <string>

namespace iblkit::api {

// A stream that keeps what is written to it and passes it on at once to `echo` (when given), so
// that a caller sees each line of a run's report as the run makes it.
class ReportBuffer : public std::streambuf {
public:
    explicit ReportBuffer(std::ostream* echo) : echo_(echo) {}
    const std::string& text() const { return text_; }

protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* text, std::streamsize count) override;
    int sync() override;

private:
    std::ostream* echo_;
    std::string text_;
};

} // namespace iblkit::api
