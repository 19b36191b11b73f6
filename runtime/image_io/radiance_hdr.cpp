#include "file_names.hpp"
#include "files.hpp"
#include "float_image.hpp"
#include "image_error.hpp"
#include "radiance_layout.hpp"

#include <stb_image.h>

#include <climits>
#include <memory>

namespace iblkit::image_io {

FloatImage readRadianceHdr(const std::filesystem::path& path) { return decodeRadianceHdr(readFileBytes(path), path); }

FloatImage decodeRadianceHdr(std::span<const std::byte> bytes, const std::filesystem::path& path) {
    const RadianceLayout layout = readRadianceLayout(bytes, path.string());
    requireCompletePixelData(bytes, layout, path.string());
    if (bytes.size() > size_t(INT_MAX)) throw ImageError(quoted(path) + " is larger than stb_image reads (2 GiB)");
    int width = 0, height = 0, channelsInFile = 0;
    const std::unique_ptr<float, void (*)(void*)> pixels(
        stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &width, &height,
                               &channelsInFile, 3),
        &stbi_image_free);
    if (!pixels) throw ImageError(quoted(path) + " is not a readable Radiance HDR image: " + stbi_failure_reason());
    const size_t count = size_t(width) * size_t(height) * 3;
    return FloatImage{uint32_t(width), uint32_t(height), 3, std::vector<float>(pixels.get(), pixels.get() + count)};
}

} // namespace iblkit::image_io
