#include "key_value_data.hpp"

#include "byte_io.hpp"

namespace iblkit::image_io::ktx2 {
namespace {

void putTerminated(ByteWriter& out, const std::string& text) {
    out.putBytes(std::as_bytes(std::span(text.data(), text.size())));
    out.put('\0');
}

} // namespace

std::vector<std::byte> keyValueData(const std::map<std::string, std::string>& entries) {
    ByteWriter out;
    for (const auto& [key, value] : entries) {
        out.put<uint32_t>(uint32_t(key.size() + 1 + value.size() + 1));
        putTerminated(out, key);
        putTerminated(out, value);
        out.padTo(4);
    }
    return out.take();
}

} // namespace iblkit::image_io::ktx2
