#include "lut_fit.hpp"

#include "converged_lut.hpp"
#include "parallel_rows.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace iblkit::reference {
namespace {

// T_0..T_degree at x in [0, 1], by the recurrence the shader unrolls.
template <typename T>
std::vector<T> chebyshev(T x, uint32_t degree) {
    std::vector<T> values(degree + 1);
    const T y = T(2) * x - T(1);
    values[0] = T(1);
    if (degree >= 1) values[1] = y;
    for (uint32_t k = 2; k <= degree; ++k) values[k] = T(2) * y * values[k - 1] - values[k - 2];
    return values;
}

// Solves the normal equations by Cholesky, which the Chebyshev basis keeps well enough
// conditioned up to degree 9 (tests/reference/lut_fit_test.cpp measures each degree's fit).
std::vector<glm::dvec2> leastSquares(const std::vector<std::vector<double>>& rows, const std::vector<glm::dvec2>& values) {
    const size_t n = rows.front().size();
    std::vector<double> normal(n * n, 0.0);
    std::vector<glm::dvec2> right(n, glm::dvec2(0));
    for (size_t r = 0; r < rows.size(); ++r)
        for (size_t i = 0; i < n; ++i) {
            right[i] += rows[r][i] * values[r];
            for (size_t j = 0; j <= i; ++j) normal[i * n + j] += rows[r][i] * rows[r][j];
        }
    for (size_t k = 0; k < n; ++k) { // lower triangle L with L Lᵀ = normal
        for (size_t j = 0; j < k; ++j) normal[k * n + k] -= normal[k * n + j] * normal[k * n + j];
        normal[k * n + k] = std::sqrt(normal[k * n + k]);
        for (size_t i = k + 1; i < n; ++i) {
            for (size_t j = 0; j < k; ++j) normal[i * n + k] -= normal[i * n + j] * normal[k * n + j];
            normal[i * n + k] /= normal[k * n + k];
        }
    }
    std::vector<glm::dvec2> solution(n);
    for (size_t i = 0; i < n; ++i) {
        glm::dvec2 sum = right[i];
        for (size_t j = 0; j < i; ++j) sum -= normal[i * n + j] * solution[j];
        solution[i] = sum / normal[i * n + i];
    }
    for (size_t i = n; i-- > 0;) {
        glm::dvec2 sum = solution[i];
        for (size_t j = i + 1; j < n; ++j) sum -= normal[j * n + i] * solution[j];
        solution[i] = sum / normal[i * n + i];
    }
    return solution;
}

// The converged LUT at the fit's nodes, u-major rows of w.
std::vector<glm::dvec2> convergedAtNodes() {
    std::vector<glm::dvec2> values(size_t(kLutFitNodes) * kLutFitNodes);
    forEachRow(kLutFitNodes, [&](uint32_t row) {
        const double w = double(row) / (kLutFitNodes - 1);
        for (uint32_t column = 0; column < kLutFitNodes; ++column) {
            const double u = double(column) / (kLutFitNodes - 1);
            values[size_t(row) * kLutFitNodes + column] = convergedBrdf(u * u * u * u, w * w);
        }
    });
    return values;
}

std::vector<glm::dvec2> fitTo(const std::vector<glm::dvec2>& values, uint32_t degree) {
    std::vector<std::vector<double>> rows;
    for (uint32_t row = 0; row < kLutFitNodes; ++row)
        for (uint32_t column = 0; column < kLutFitNodes; ++column) {
            const auto tu = chebyshev(double(column) / (kLutFitNodes - 1), degree);
            const auto tw = chebyshev(double(row) / (kLutFitNodes - 1), degree);
            std::vector<double> basis;
            for (uint32_t a = 0; a <= degree; ++a)
                for (uint32_t b = 0; b <= degree; ++b) basis.push_back(tu[a] * tw[b]);
            rows.push_back(std::move(basis));
        }
    return leastSquares(rows, values);
}

void checkDegree(uint32_t degree) {
    if (degree == 0 || degree > kMaxLutFitDegree)
        throw std::invalid_argument("the polynomial LUT takes degrees 1 to " + std::to_string(kMaxLutFitDegree) + ", not " +
                                    std::to_string(degree));
}

} // namespace

std::vector<glm::dvec2> fitBrdfLut(uint32_t degree) {
    checkDegree(degree);
    return fitTo(convergedAtNodes(), degree);
}

std::vector<std::vector<glm::dvec2>> fitBrdfLutEveryDegree() {
    const auto values = convergedAtNodes();
    std::vector<std::vector<glm::dvec2>> fits;
    for (uint32_t degree = 1; degree <= kMaxLutFitDegree; ++degree) fits.push_back(fitTo(values, degree));
    return fits;
}

template <typename T>
glm::vec<2, T> evaluateBrdfLutFit(T ndotv, T roughness, const std::vector<glm::vec<2, T>>& coefficients) {
    const auto degree = uint32_t(std::lround(std::sqrt(double(coefficients.size())))) - 1;
    const auto tu = chebyshev(std::sqrt(std::sqrt(ndotv)), degree), tw = chebyshev(std::sqrt(roughness), degree);
    glm::vec<2, T> sum(0);
    for (uint32_t a = 0; a <= degree; ++a)
        for (uint32_t b = 0; b <= degree; ++b) sum += coefficients[a * (degree + 1) + b] * (tu[a] * tw[b]);
    return glm::clamp(sum, T(0), T(1));
}

template <typename T>
std::vector<T> brdfLutFromFit(uint32_t size, const std::vector<glm::vec<2, T>>& coefficients) {
    std::vector<T> texels(size_t(size) * size * 2);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const auto value = evaluateBrdfLutFit((T(x) + T(0.5)) / T(size), (T(y) + T(0.5)) / T(size), coefficients);
            texels[(size_t(y) * size + x) * 2] = value.x;
            texels[(size_t(y) * size + x) * 2 + 1] = value.y;
        }
    return texels;
}

std::string brdfLutFitInclude() {
    std::string text =
        "// Common/BrdfLutFit.fxh — generated by `iblkit lut-fit`; do not edit.\n"
        "// BrdfLutFitCS's coefficients for each degree (SAMPLE_COUNT): reference::fitBrdfLut's least-squares\n"
        "// fit to the converged LUT, rounded to float, a-major over T_a(2u - 1) T_b(2w - 1).\n"
        "#ifndef COMMON_BRDF_LUT_FIT_FXH\n#define COMMON_BRDF_LUT_FIT_FXH\n";
    const auto fits = fitBrdfLutEveryDegree();
    char number[32];
    for (uint32_t degree = 1; degree <= kMaxLutFitDegree; ++degree) {
        const auto& coefficients = fits[degree - 1];
        text += (degree == 1 ? "#if" : "#elif") + std::string(" SAMPLE_COUNT == ") + std::to_string(degree) + "\n";
        text += "static const float2 FitCoefficients[" + std::to_string(coefficients.size()) + "] = {\n";
        for (const auto& c : coefficients) {
            text += "    float2( ";
            std::snprintf(number, sizeof number, "%.9gf", double(float(c.x)));
            text += number;
            text += ", ";
            std::snprintf(number, sizeof number, "%.9gf", double(float(c.y)));
            text += number;
            text += " ),\n";
        }
        text += "};\n";
    }
    text += "#endif\n#endif\n";
    return text;
}

template glm::vec<2, float> evaluateBrdfLutFit<float>(float, float, const std::vector<glm::vec<2, float>>&);
template glm::vec<2, double> evaluateBrdfLutFit<double>(double, double, const std::vector<glm::vec<2, double>>&);
template std::vector<float> brdfLutFromFit<float>(uint32_t, const std::vector<glm::vec<2, float>>&);
template std::vector<double> brdfLutFromFit<double>(uint32_t, const std::vector<glm::vec<2, double>>&);

} // namespace iblkit::reference
