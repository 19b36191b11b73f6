#include "render/heat_map.hpp"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>

namespace iblkit::render {
namespace {

constexpr uint32_t kLegendHeight = 40, kBarTop = 8, kBarHeight = 10, kMargin = 16, kGlyphScale = 2;

// A 3x5 pixel font for the legend's labels: five rows of three bits, the high bit leftmost.
struct Glyph {
    char character;
    std::array<uint8_t, 5> rows;
};
constexpr Glyph kGlyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'+', {0, 2, 7, 2, 0}}, {'-', {0, 0, 7, 0, 0}},
    {'%', {5, 1, 2, 4, 5}}, {'.', {0, 0, 0, 0, 2}},
};

glm::vec3 colourOf(double error) {
    const float t = float(std::clamp(error / kHeatMapRange, -1.0, 1.0));
    const glm::vec3 white(1.f), darker(0.23f, 0.30f, 0.75f), brighter(0.71f, 0.02f, 0.15f);
    return t < 0 ? glm::mix(white, darker, -t) : glm::mix(white, brighter, t);
}

class Canvas {
public:
    explicit Canvas(Rgba8Image& image) : image_(image) {}
    void set(uint32_t x, uint32_t y, glm::vec3 colour) {
        if (x >= image_.width || y >= image_.height) return;
        auto* texel = &image_.rgba[4 * (size_t(y) * image_.width + x)];
        for (int c = 0; c < 3; ++c) texel[c] = uint8_t(std::lround(std::clamp(colour[c], 0.f, 1.f) * 255.f));
        texel[3] = 255;
    }
    void text(uint32_t centreX, uint32_t top, std::string_view label) {
        const uint32_t advance = 4 * kGlyphScale;
        uint32_t x = centreX - std::min(centreX, uint32_t(label.size()) * advance / 2);
        for (const char character : label) {
            for (const auto& glyph : kGlyphs)
                if (glyph.character == character) drawGlyph(x, top, glyph);
            x += advance;
        }
    }

private:
    void drawGlyph(uint32_t left, uint32_t top, const Glyph& glyph) {
        for (uint32_t row = 0; row < 5 * kGlyphScale; ++row)
            for (uint32_t column = 0; column < 3 * kGlyphScale; ++column)
                if (glyph.rows[row / kGlyphScale] & (4 >> (column / kGlyphScale))) set(left + column, top + row, glm::vec3(1.f));
    }
    Rgba8Image& image_;
};

std::string percent(double value) {
    const long rounded = std::lround(100 * value);
    return (rounded > 0 ? "+" : "") + std::to_string(rounded) + "%";
}

void drawLegend(Canvas& canvas, uint32_t width, uint32_t top) {
    if (width <= 2 * kMargin) return;
    const uint32_t barWidth = width - 2 * kMargin;
    for (uint32_t x = 0; x < barWidth; ++x) {
        const double error = (2.0 * (x + 0.5) / barWidth - 1.0) * kHeatMapRange;
        for (uint32_t y = 0; y < kBarHeight; ++y) canvas.set(kMargin + x, top + kBarTop + y, colourOf(error));
    }
    for (const double tick : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        const auto x = uint32_t(kMargin + (tick + 1.0) / 2.0 * (barWidth - 1));
        for (uint32_t y = 0; y < 4; ++y) canvas.set(x, top + kBarTop + kBarHeight + y, glm::vec3(1.f));
        canvas.text(x, top + kBarTop + kBarHeight + 6, percent(tick * kHeatMapRange));
    }
}

} // namespace

Rgba8Image heatMap(const std::vector<double>& errors, const std::vector<bool>& covered, uint32_t width, uint32_t height) {
    Rgba8Image image{width, height + kLegendHeight, {}};
    image.rgba.assign(size_t(image.width) * image.height * 4, 0);
    for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
    Canvas canvas(image);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const size_t pixel = size_t(y) * width + x;
            if (covered[pixel]) canvas.set(x, y, colourOf(errors[pixel]));
        }
    drawLegend(canvas, width, height);
    return image;
}

} // namespace iblkit::render
