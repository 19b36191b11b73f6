#include "lut_quadrature.hpp"

#include "parallel_rows.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace iblkit::reference {
namespace {

constexpr uint32_t MAX_NODES = 16;
constexpr uint32_t SERIES_TERMS = 24;
constexpr double FAR_POLE = 1.25;
constexpr double PANEL_RATIO = 4;
constexpr double NEGLIGIBLE = 1e-6;

template <typename T> using Pair = glm::vec<2, T>;
template <typename T> constexpr T pi = std::numbers::pi_v<T>;

template <typename T>
T PreciseAtan(T x) {
    T offset = 0;
    if (x > T(2.414213562)) {
        offset = pi<T> / T(2);
        x = T(-1) / x;
    } else if (x > T(0.414213562)) {
        offset = pi<T> / T(4);
        x = (x - T(1)) / (x + T(1));
    }
    const T z = x * x;
    return offset + ((((T(8.05374449538e-2) * z - T(1.38776856032e-1)) * z + T(1.99777106478e-1)) * z - T(3.33329491539e-1)) * z * x + x);
}

template <typename T>
T PreciseAsin(T x) {
    const T complement = std::sqrt((T(1) - x) * (T(1) + x));
    return x > complement ? pi<T> / T(2) - PreciseAtan(complement / x) : PreciseAtan(x / complement);
}

template <typename T>
struct GaussRule {
    std::array<T, MAX_NODES> nodes{}, weights{};
};

template <typename T>
GaussRule<T> BuildGaussLegendre(uint32_t count) {
    GaussRule<T> rule;
    for (uint32_t i = 0; i < count; ++i) {
        T x = std::cos(pi<T> * (T(i) + T(0.75)) / (T(count) + T(0.5)));
        T derivative = 1;
        for (uint32_t iteration = 0; iteration < 6; ++iteration) {
            T previous = 1, current = x;
            for (uint32_t j = 2; j <= count; ++j) {
                const T next = ((T(2) * T(j) - T(1)) * x * current - (T(j) - T(1)) * previous) / T(j);
                previous = current;
                current = next;
            }
            derivative = T(count) * (x * current - previous) / (x * x - T(1));
            x -= current / derivative;
        }
        rule.nodes[i] = T(0.5) - T(0.5) * x;
        rule.weights[i] = T(1) / ((T(1) - x * x) * derivative * derivative);
    }
    return rule;
}

template <typename T>
struct LutSetting {
    T ndotv, ndotvComplement, sinV;
    T alpha2, k, kappa;
    T theta1;
    T visibilityV;
    uint32_t nodes;
    GaussRule<T> gauss;
};

template <typename T>
T GgxAt(T cosH, T sinH, T alpha2) {
    const T spread = sinH * sinH + alpha2 * cosH * cosH;
    return alpha2 / (pi<T> * spread * spread);
}

template <typename T>
std::array<T, 7> BiasSeries(T p, T q, T qComplement) {
    const T m2 = qComplement * qComplement, p2 = p * p;
    std::array<T, 6> binomial;
    binomial[0] = m2 * m2 * qComplement;
    binomial[1] = T(-5) * m2 * m2 * p;
    binomial[2] = T(10) * m2 * qComplement * p2;
    binomial[3] = T(-10) * m2 * p2 * p;
    binomial[4] = T(5) * qComplement * p2 * p2;
    binomial[5] = -p2 * p2 * p;
    std::array<T, 7> d;
    d[0] = q * binomial[0];
    for (uint32_t k = 1; k < 6; ++k) d[k] = q * binomial[k] + p * binomial[k - 1];
    d[6] = p * binomial[5];
    std::array<T, 7> a;
    a[0] = d[0] + d[2] / T(2) + T(3) * d[4] / T(8) + T(10) * d[6] / T(32);
    a[1] = d[1] + T(3) * d[3] / T(4) + T(10) * d[5] / T(16);
    a[2] = d[2] / T(2) + d[4] / T(2) + T(15) * d[6] / T(32);
    a[3] = d[3] / T(4) + T(5) * d[5] / T(16);
    a[4] = d[4] / T(8) + T(6) * d[6] / T(32);
    a[5] = d[5] / T(16);
    a[6] = d[6] / T(32);
    return a;
}

template <typename T>
Pair<T> RingPoleNear(const std::array<T, 7>& a, T p, T q, const std::array<T, 7>& S, T x, T gap, T tanHalfArc) {
    const T s = std::sqrt(std::abs(T(1) + x) / (T(1) - x)), y = tanHalfArc * s;
    T ratio;
    if (y < T(0.125)) {
        const T z = (x > T(-1) ? T(1) : T(-1)) * y * y;
        ratio = tanHalfArc * (T(1) + z * (T(1) / T(3) + z * (T(1) / T(5) + z * (T(1) / T(7) + z / T(9)))));
    } else if (x > T(-1))
        ratio = T(0.5) * std::log((T(1) + y) * (T(1) + y) * (T(1) - x) / (gap * (T(1) + tanHalfArc * tanHalfArc))) / s;
    else
        ratio = PreciseAtan(y) / s;
    T previous = T(2) * ratio / (T(1) - x);
    T current = x * previous + S[0];
    Pair<T> sums(a[0] * previous + a[1] * current, q * previous + p * current);
    for (uint32_t j = 1; j < 6; ++j) {
        const T next = T(2) * x * current - previous + T(2) * S[j];
        previous = current;
        current = next;
        sums.x += a[j + 1] * current;
    }
    return sums;
}

template <typename T>
Pair<T> RingPoleFar(const std::array<T, 7>& a, T p, T q, const std::array<T, 7>& S, T r, T cosArc) {
    std::array<T, 7> right;
    right[6] = 0;
    for (int n = 5; n >= 0; --n) right[n] = (right[n + 1] + a[n + 1]) * r;
    T left = a[0];
    const T atZero = left + right[0];
    T bias = S[0] * atZero, head = 0, power = 1, c6 = 0, fifthPower = 0;
    for (uint32_t n = 1; n < 7; ++n) {
        left = left * r + a[n];
        const T below = power;
        power *= r;
        const T cn = left + right[n] + power * atZero;
        if (n < 6) {
            bias += S[n] * cn;
            head += S[n] * below;
        } else {
            c6 = cn;
            fifthPower = below;
        }
    }
    T sinPrevious = S[5] * T(5), sinCurrent = S[6] * T(6);
    T tail = 0, weight = 1;
    for (uint32_t m = 6; m < 6 + SERIES_TERMS && std::abs(weight) > T(1e-7); ++m) {
        tail += weight * sinCurrent / T(m);
        const T sinNext = T(2) * cosArc * sinCurrent - sinPrevious;
        sinPrevious = sinCurrent;
        sinCurrent = sinNext;
        weight *= r;
    }
    const T vdoth = S[0] * (q + p * r) + (T(2) * q * r + p * (T(1) + r * r)) * (head + fifthPower * tail);
    return {bias + c6 * tail, vdoth};
}

template <typename T>
Pair<T> RingIntegral(const LutSetting<T>& s, T cosH, T sinH, T tanHalfArc, bool fullRing) {
    const T p = s.sinV * sinH, q = s.ndotv * cosH;
    const T qComplement = s.ndotvComplement + s.ndotv * sinH * sinH / (T(1) + cosH);
    const T A = T(2) * p * cosH, B = s.ndotv * (cosH - sinH) * (cosH + sinH);
    const auto a = BiasSeries(p, q, qComplement);
    const T beta = B + s.kappa;
    Pair<T> polynomial, pole;
    if (fullRing) {
        const T rOverA = T(-1) / (beta + std::sqrt((beta - A) * (beta + A))), r = rOverA * A;
        T sum = a[6];
        for (int j = 5; j >= 0; --j) sum = sum * r + a[j];
        polynomial = pi<T> * Pair<T>(a[0], q);
        pole = (T(-2) * s.kappa * rOverA / (T(1) - r * r)) * pi<T> * Pair<T>(sum, q + p * r);
    } else {
        const T t2 = tanHalfArc * tanHalfArc;
        const T cosArc = (T(1) - t2) / (T(1) + t2), sinArc = T(2) * tanHalfArc / (T(1) + t2);
        std::array<T, 7> S;
        S[0] = T(2) * PreciseAtan(tanHalfArc);
        T sinPrevious = 0, sinCurrent = sinArc;
        for (uint32_t n = 1; n < 7; ++n) {
            S[n] = sinCurrent / T(n);
            const T sinNext = T(2) * cosArc * sinCurrent - sinPrevious;
            sinPrevious = sinCurrent;
            sinCurrent = sinNext;
        }
        polynomial = Pair<T>(0, q * S[0] + p * S[1]);
        for (uint32_t j = 0; j < 7; ++j) polynomial.x += a[j] * S[j];
        if (beta > T(FAR_POLE) * A) {
            const T rOverA = T(-1) / (beta + std::sqrt((beta - A) * (beta + A))), r = rOverA * A;
            pole = (T(-2) * s.kappa * rOverA / (T(1) - r * r)) * RingPoleFar(a, p, q, S, r, cosArc);
        } else
            pole = (s.kappa / A) * RingPoleNear(a, p, q, S, -beta / A, s.kappa / A, tanHalfArc);
    }
    const Pair<T> biasAndTotal = (polynomial - pole) / (T(1) - s.k);
    return {biasAndTotal.y - biasAndTotal.x, biasAndTotal.x};
}

template <typename T>
bool PanelIsNegligible(const LutSetting<T>& s, T lobeShare, T leastCosH) {
    return s.visibilityV * lobeShare < T(NEGLIGIBLE) * leastCosH;
}

template <typename T>
T EtaAt(T theta, T alpha2) {
    const T t = std::tan(theta);
    return alpha2 / (t * t + alpha2);
}

template <typename T>
Pair<T> FullCapIntegral(const LutSetting<T>& s) {
    const T t1 = std::tan(s.theta1), tan2 = t1 * t1;
    const T eta1 = s.alpha2 / (tan2 + s.alpha2), length = tan2 / (tan2 + s.alpha2);
    Pair<T> sum(0);
    if (!(length > T(0))) return sum;
    const T halfPinch = std::min(PreciseAsin(std::min(s.kappa, T(1))), s.theta1) / T(2);
    T scale = std::max(eta1 - EtaAt(s.theta1 + halfPinch, s.alpha2), T(1e-15));
    if (!(scale < length / T(PANEL_RATIO))) scale = length;
    for (T near = 0, far = scale; near < length; near = far, far *= T(PANEL_RATIO)) {
        const T end = std::min(far, length), width = end - near;
        const T leastEta = eta1 + near;
        const T leastCosH = std::sqrt(leastEta / (leastEta + s.alpha2 * (length - near)));
        if (PanelIsNegligible(s, width, leastCosH)) continue;
        for (uint32_t i = 0; i < s.nodes; ++i) {
            const T u = near + width * s.gauss.nodes[i];
            const T eta = eta1 + u, etaComplement = length - u, denominator = eta + s.alpha2 * etaComplement;
            const T cosH = std::sqrt(eta / denominator), sinH = std::sqrt(s.alpha2 * etaComplement / denominator);
            sum += s.gauss.weights[i] * width / cosH * RingIntegral(s, cosH, sinH, T(0), true);
        }
    }
    return sum / pi<T>;
}

template <typename T>
T EtaBesideHorizon(T psi, T alpha2) {
    const T t = std::tan(psi), scaled = alpha2 * t * t;
    return scaled / (T(1) + scaled);
}

template <typename T>
Pair<T> PartialBandIntegral(const LutSetting<T>& s) {
    const T width = pi<T> / T(2) - T(2) * s.theta1;
    Pair<T> sum(0);
    if (!(width > T(0))) return sum;
    const T halfPinch = PreciseAsin(std::min(s.kappa, T(1))) / T(2);
    T scale = std::max(s.theta1 > T(0) ? std::min(s.theta1, halfPinch) : halfPinch, T(1e-15));
    const T half = width / T(2);
    if (!(scale < half / T(PANEL_RATIO))) scale = half;
    for (uint32_t side = 0; side < 2; ++side)
        for (T near = 0, far = scale; near < half; near = far, far *= T(PANEL_RATIO)) {
            const T end = std::min(far, half);
            const T lobeShare = side == 0 ? EtaAt(s.theta1 + near, s.alpha2) - EtaAt(s.theta1 + end, s.alpha2)
                                          : EtaBesideHorizon(s.theta1 + end, s.alpha2) - EtaBesideHorizon(s.theta1 + near, s.alpha2);
            const T leastCosH = side == 0 ? std::cos(s.theta1 + end) : std::sin(s.theta1 + near);
            if (PanelIsNegligible(s, lobeShare, leastCosH)) continue;
            for (uint32_t i = 0; i < s.nodes; ++i) {
                const T t = s.gauss.nodes[i];
                const bool endPanel = near == T(0);
                const T fromEnd = endPanel ? end * t * t : near + (end - near) * t;
                const T jacobian = endPanel ? end * T(2) * t : end - near;
                const T angle = s.theta1 + fromEnd, cosAngle = std::cos(angle), sinAngle = std::sin(angle);
                const T cosH = side == 0 ? cosAngle : sinAngle, sinH = side == 0 ? sinAngle : cosAngle;
                const T nearSin = std::sin(T(2) * fromEnd), farSin = std::sin(T(2) * (T(2) * s.theta1 + fromEnd));
                const T tanHalfArc = side == 0 ? std::sqrt(farSin) / std::sqrt(nearSin) : std::sqrt(nearSin) / std::sqrt(farSin);
                const T density = T(2) * GgxAt(cosH, sinH, s.alpha2) * sinH;
                sum += s.gauss.weights[i] * jacobian * density * RingIntegral(s, cosH, sinH, tanHalfArc, false);
            }
        }
    return sum;
}

} // namespace

template <typename T>
glm::vec<2, T> IntegrateBrdfQuadrature(T ndotv, T ndotvComplement, T roughness, uint32_t nodes) {
    nodes = std::clamp(nodes, 1u, MAX_NODES);
    const T alpha = roughness * roughness, alpha2 = alpha * alpha, k = alpha / T(2);
    const T fc = std::pow(ndotvComplement, T(5));
    if (alpha2 < T(1e-30)) return {T(1) - fc, fc};
    LutSetting<T> s;
    s.ndotv = ndotv;
    s.ndotvComplement = ndotvComplement;
    s.sinV = std::sqrt(ndotvComplement * (T(1) + ndotv));
    s.alpha2 = alpha2;
    s.k = k;
    s.kappa = k / (T(1) - k);
    s.theta1 = PreciseAsin(ndotv) / T(2);
    s.visibilityV = T(1) / (ndotv * (T(1) - k) + k);
    s.nodes = nodes;
    s.gauss = BuildGaussLegendre<T>(nodes);
    return s.visibilityV * (FullCapIntegral(s) + PartialBandIntegral(s));
}

template <typename T>
std::vector<T> brdfLutQuadrature(uint32_t size, uint32_t nodes) {
    std::vector<T> lut(size_t(size) * size * 2);
    forEachRow(size, [&](uint32_t y) {
        const T roughness = (T(y) + T(0.5)) / T(size);
        for (uint32_t x = 0; x < size; ++x) {
            const auto scaleBias = IntegrateBrdfQuadrature((T(x) + T(0.5)) / T(size), (T(size - x) - T(0.5)) / T(size), roughness, nodes);
            lut[(size_t(y) * size + x) * 2] = scaleBias.x;
            lut[(size_t(y) * size + x) * 2 + 1] = scaleBias.y;
        }
    });
    return lut;
}

template std::vector<float> brdfLutQuadrature(uint32_t, uint32_t);
template std::vector<double> brdfLutQuadrature(uint32_t, uint32_t);
template glm::vec<2, float> IntegrateBrdfQuadrature(float, float, float, uint32_t);
template glm::vec<2, double> IntegrateBrdfQuadrature(double, double, double, uint32_t);

} // namespace iblkit::reference
