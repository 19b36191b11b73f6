#include "api/report_stream.hpp"

namespace iblkit::api {

ReportBuffer::int_type ReportBuffer::overflow(int_type c) {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char character = traits_type::to_char_type(c);
    xsputn(&character, 1);
    return c;
}

std::streamsize ReportBuffer::xsputn(const char* text, std::streamsize count) {
    text_.append(text, size_t(count));
    if (echo_) echo_->write(text, count);
    return count;
}

int ReportBuffer::sync() {
    if (echo_) echo_->flush();
    return 0;
}

} // namespace iblkit::api
