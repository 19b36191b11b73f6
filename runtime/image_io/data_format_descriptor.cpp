#include "data_format_descriptor.hpp"

#include "byte_io.hpp"

#include <array>
#include <bit>

namespace iblkit::image_io::ktx2 {
namespace {

// Khronos Data Format Specification 1.3, the basic descriptor block.
constexpr uint32_t kVendorKhronos = 0, kDescriptorTypeBasic = 0, kVersion1_3 = 2;
constexpr uint32_t kModelRgbsda = 1, kPrimariesBt709 = 1, kTransferLinear = 1, kFlagsAlphaStraight = 0;
constexpr std::array<uint32_t, 4> kChannelIds = {0, 1, 2, 15}; // RGBSDA red, green, blue, alpha
constexpr uint32_t kQualifierFloat = 0x80, kQualifierSigned = 0x40;
constexpr size_t kBlockHeaderBytes = 24, kSampleBytes = 16;

void putSample(ByteWriter& out, uint32_t channel, uint32_t bits) {
    const uint32_t channelType = kChannelIds[channel] | kQualifierFloat | kQualifierSigned;
    out.put<uint32_t>((channel * bits) | ((bits - 1) << 16) | (channelType << 24)); // bitOffset, bitLength, channelType
    out.put<uint32_t>(0);                                                           // samplePosition0..3
    // KTX-Software's createDFDUnpacked gives SFLOAT samples the range -1.0 to 1.0.
    out.put<uint32_t>(std::bit_cast<uint32_t>(-1.0f)); // sampleLower
    out.put<uint32_t>(std::bit_cast<uint32_t>(1.0f));  // sampleUpper
}

} // namespace

std::vector<std::byte> dataFormatDescriptor(PixelFormat format) {
    const uint32_t channels = channelCount(format), bits = 8 * bytesPerChannel(format);
    const uint32_t blockBytes = uint32_t(kBlockHeaderBytes + kSampleBytes * channels);
    ByteWriter out;
    out.put<uint32_t>(4 + blockBytes); // dfdTotalSize
    out.put<uint32_t>(kVendorKhronos | (kDescriptorTypeBasic << 17));
    out.put<uint32_t>(kVersion1_3 | (blockBytes << 16));
    out.put<uint32_t>(kModelRgbsda | (kPrimariesBt709 << 8) | (kTransferLinear << 16) | (kFlagsAlphaStraight << 24));
    out.put<uint32_t>(0);                     // texelBlockDimension0..3: 1x1x1x1, stored minus one
    out.put<uint32_t>(bytesPerTexel(format)); // bytesPlane0; bytesPlane1..3 = 0
    out.put<uint32_t>(0);                     // bytesPlane4..7
    for (uint32_t channel = 0; channel < channels; ++channel) putSample(out, channel, bits);
    return out.take();
}

} // namespace iblkit::image_io::ktx2
