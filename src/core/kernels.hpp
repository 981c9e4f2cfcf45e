#pragma once
/// \file
/// SPH smoothing kernels in 3D or 2D (WorldDef::dimensions), support radius h (zero for
/// r ≥ h), each with value, gradient and Laplacian. Each kernel has the same shape in both;
/// only its normalisation σ (∫W dV = 1 in 3D, ∫W dA = 1 in 2D) and the Laplacian's
/// (d − 1) W'/r term depend on the dimension d. tests/test_kernels.cpp integrates them.
///
/// Poly6, Spiky and Viscosity follow Müller, Charypar & Gross 2003, "Particle-based fluid
/// simulation for interactive applications", eqs. (20)–(22), in the corrected forms of
/// SPEC.md §1. The smoothing kernel of the incompressible solvers is Monaghan's 1992 cubic
/// spline rescaled to support h (as in SPlisHSPlasH's CubicKernel) or Wendland's C2.
/// Gradients take r⃗ = x_i − x_j and r = |r⃗|.

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

#include <tide/defs.hpp>

namespace tide::kernels {

inline constexpr float pi = std::numbers::pi_v<float>;

/// W = 315/(64π h⁹) (h² − r²)³ in 3D, 4/(π h⁸) (h² − r²)³ in 2D. Smooth at r = 0: used for density.
struct Poly6 {
    float h, h2, norm, gradNorm;
    int dimensions;
    explicit Poly6(float support, int dims = 3)
        : h(support), h2(support * support),
          norm(dims == 2 ? 4.0f / (pi * h2 * h2 * h2 * h2) : 315.0f / (64.0f * pi * h2 * h2 * h2 * h2 * support)),
          gradNorm(dims == 2 ? -24.0f / (pi * h2 * h2 * h2 * h2) : -945.0f / (32.0f * pi * h2 * h2 * h2 * h2 * support)),
          dimensions(dims) {}
    /// Value from r² (no square root needed).
    [[nodiscard]] float valueSq(float r2) const {
        if (r2 >= h2) return 0.0f;
        const float d = h2 - r2;
        return norm * d * d * d;
    }
    [[nodiscard]] float value(float r) const { return valueSq(r * r); }
    [[nodiscard]] glm::vec3 gradient(const glm::vec3& rij, float r) const {
        if (r >= h) return glm::vec3(0.0f);
        const float d = h2 - r * r;
        return (gradNorm * d * d) * rij;
    }
    /// ∇²W = W'' + (d − 1)W'/r = −6σ (h² − r²)(d h² − (d + 4) r²).
    [[nodiscard]] float laplacian(float r) const {
        if (r >= h) return 0.0f;
        const float r2 = r * r;
        if (dimensions == 2) return gradNorm * (h2 - r2) * (2.0f * h2 - 6.0f * r2);
        return gradNorm * (h2 - r2) * (3.0f * h2 - 7.0f * r2);
    }
};

/// W = 15/(π h⁶) (h − r)³ in 3D, 10/(π h⁵) (h − r)³ in 2D. Its gradient does not vanish at
/// r → 0, so close particles still repel: used for pressure.
struct Spiky {
    float h, norm, gradNorm;
    int dimensions;
    explicit Spiky(float support, int dims = 3)
        : h(support),
          norm(dims == 2 ? 10.0f / (pi * support * support * support * support * support)
                         : 15.0f / (pi * support * support * support * support * support * support)),
          gradNorm(dims == 2 ? -30.0f / (pi * support * support * support * support * support)
                             : -45.0f / (pi * support * support * support * support * support * support)),
          dimensions(dims) {}
    [[nodiscard]] float value(float r) const {
        if (r >= h) return 0.0f;
        const float d = h - r;
        return norm * d * d * d;
    }
    /// ∇W = −45/(π h⁶) (h − r)² r̂; zero at r = 0 exactly (direction undefined).
    [[nodiscard]] glm::vec3 gradient(const glm::vec3& rij, float r) const {
        if (r >= h || r <= 0.0f) return glm::vec3(0.0f);
        const float d = h - r;
        return (gradNorm * d * d / r) * rij;
    }
    /// Magnitude factor of the gradient, −45/(π h⁶)(h − r)², for callers holding r̂.
    [[nodiscard]] float gradientScale(float r) const {
        if (r >= h) return 0.0f;
        const float d = h - r;
        return gradNorm * d * d;
    }
    /// ∇²W = W'' + (d − 1)W'/r: 90/(π h⁶) (h − r)(2r − h)/r in 3D, 30/(π h⁵) (h − r)(3r − h)/r in 2D.
    [[nodiscard]] float laplacian(float r) const {
        if (r >= h) return 0.0f;
        if (dimensions == 2) return -gradNorm * (h - r) * (3.0f * r - h) / r;
        return -6.0f * gradNorm / 3.0f * (h - r) * (2.0f * r - h) / r;
    }
};

/// W = 15/(2π h³) (−r³/(2h³) + r²/h² + h/(2r) − 1). Its Laplacian 45/(π h⁶)(h − r) is
/// positive everywhere: used for viscosity. In 2D (W's factor 10/(3π h²)) the Laplacian is
/// taken as 40/(π h⁵)(h − r): the same shape with the second moment ∫ r² ∇²W dA = 2d that makes
/// Σ_j V_j (v_j − v_i) ∇²W_ij approximate ∇²v (its true 2D Laplacian is singular at r = 0).
struct Viscosity {
    float h, norm, lapNorm;
    explicit Viscosity(float support, int dims = 3)
        : h(support),
          norm(dims == 2 ? 10.0f / (3.0f * pi * support * support) : 15.0f / (2.0f * pi * support * support * support)),
          lapNorm(dims == 2 ? 40.0f / (pi * support * support * support * support * support)
                            : 45.0f / (pi * support * support * support * support * support * support)) {}
    [[nodiscard]] float value(float r) const {
        if (r >= h || r <= 0.0f) return 0.0f;
        const float q = r / h;
        return norm * (-0.5f * q * q * q + q * q + 0.5f / q - 1.0f);
    }
    [[nodiscard]] glm::vec3 gradient(const glm::vec3& rij, float r) const {
        if (r >= h || r <= 0.0f) return glm::vec3(0.0f);
        const float h3 = h * h * h;
        return (norm * (-1.5f * r / h3 + 2.0f / (h * h) - 0.5f * h / (r * r * r))) * rij;
    }
    [[nodiscard]] float laplacian(float r) const { return r >= h ? 0.0f : lapNorm * (h - r); }
};

/// The smoothing kernel of the SPH sums, support h (q = r/h), in one of two shapes:
/// - the cubic B-spline of Monaghan 1992: σ(6q³ − 6q² + 1) for q ≤ ½, 2σ(1 − q)³ for q ≤ 1,
///   σ = 8/(π h³) in 3D; in 2D Monaghan's 10/(7π h_m²) at his support 2h_m = h, σ = 40/(7π h²);
/// - Wendland's C2 function (Wendland 1995, as Dehnen & Aly 2012, table 1):
///   σ(1 − q)⁴(1 + 4q), σ = 21/(2π h³) in 3D, 7/(π h²) in 2D.
/// The SIMD pair sums (solvers/pair_sums.cpp) evaluate the same expressions.
struct SmoothingKernel {
    float h, invH, sigma;
    KernelShape shape;
    int dimensions;
    explicit SmoothingKernel(float support, KernelShape kernelShape = KernelShape::CubicSpline, int dims = 3)
        : h(support), invH(1.0f / support),
          sigma(dims == 2 ? (kernelShape == KernelShape::WendlandC2 ? 7.0f : 40.0f / 7.0f) / (pi * support * support)
                          : (kernelShape == KernelShape::WendlandC2 ? 21.0f / 2.0f : 8.0f) / (pi * support * support * support)),
          shape(kernelShape), dimensions(dims) {}
    // Each piece as one expression without branches on q (the cubic spline's two as
    // 2(1 − q)₊³ − 8(½ − q)₊³): the pair loops evaluate it per neighbour, where a branch on
    // q would mispredict. The branch on the shape is the same for every call.
    [[nodiscard]] float value(float r) const {
        const float q = r * invH;
        const float outer = std::max(1.0f - q, 0.0f);
        if (shape == KernelShape::WendlandC2) return sigma * outer * outer * outer * outer * (1.0f + 4.0f * q);
        const float inner = std::max(0.5f - q, 0.0f);
        return sigma * (2.0f * outer * outer * outer - 8.0f * inner * inner * inner);
    }
    /// dW/dr: σ/h (−6(1 − q)₊² + 24(½ − q)₊²), or σ/h · (−20 q (1 − q)₊³).
    [[nodiscard]] float derivative(float r) const {
        const float q = r * invH;
        const float outer = std::max(1.0f - q, 0.0f);
        if (shape == KernelShape::WendlandC2) return sigma * invH * (-20.0f * q * outer * outer * outer);
        const float inner = std::max(0.5f - q, 0.0f);
        return sigma * invH * (24.0f * inner * inner - 6.0f * outer * outer);
    }
    /// lim r→0 of W'(r)/r, the most negative gradient factor: −12σ/h² or −20σ/h².
    [[nodiscard]] float gradientFactorAtZero() const {
        return (shape == KernelShape::WendlandC2 ? -20.0f : -12.0f) * sigma * invH * invH;
    }
    [[nodiscard]] glm::vec3 gradient(const glm::vec3& rij, float r) const {
        if (r <= 0.0f) return glm::vec3(0.0f);
        return (derivative(r) / r) * rij;
    }
    /// ∇²W = W'' + (d − 1)W'/r.
    [[nodiscard]] float laplacian(float r) const {
        const float q = r * invH;
        if (q >= 1.0f || r <= 0.0f) return 0.0f;
        float second;
        if (shape == KernelShape::WendlandC2)
            second = sigma * invH * invH * (-20.0f * (1.0f - q) * (1.0f - q) * (1.0f - 4.0f * q));
        else
            second = q <= 0.5f ? sigma * invH * invH * (36.0f * q - 12.0f) : sigma * invH * invH * 12.0f * (1.0f - q);
        return second + static_cast<float>(dimensions - 1) * derivative(r) / r;
    }
};

/// The cohesion spline of Akinci, Akinci & Teschner 2013 (eq. 2), support c:
/// C(r) = 32/(π c⁹) · { (c − r)³ r³ for c/2 < r ≤ c;  2(c − r)³ r³ − c⁶/64 for 0 < r ≤ c/2; 0 else }.
/// Positive (attracting) beyond 0.273 c, peaking at c/2 with 1/(2π c³), negative (repelling)
/// closer in. A force shape, not a normalised smoothing kernel. In 2D it carries one power of c
/// less (32/(π c⁸)): masses there are per metre of width (ρ s² against ρ s³), so γ m_j C(r)
/// keeps the scale it has in 3D and γ means the same in both.
struct Cohesion {
    float c, norm, c6over64;
    explicit Cohesion(float support, int dims = 3)
        : c(support), norm(32.0f / (pi * support * support * support * support * support * support * support * support *
                                    (dims == 2 ? 1.0f : support))),
          c6over64(support * support * support * support * support * support / 64.0f) {}
    [[nodiscard]] float value(float r) const {
        if (r >= c || r <= 0.0f) return 0.0f;
        const float outer = (c - r) * r;
        const float cube = outer * outer * outer;
        return norm * (2.0f * r > c ? cube : 2.0f * cube - c6over64);
    }
};

/// The adhesion spline of Akinci, Akinci & Teschner 2013 (eq. 7), support c:
/// A(r) = 0.007/c^3.25 · (−4r²/c + 6r − 2c)^¼ for c/2 < r ≤ c, 0 else: attraction to a
/// boundary particle only at the distance of the first layers, peaking at 3c/4. In 2D
/// 0.007/c^2.25, for the reason Cohesion gives (boundary volumes are areas there).
struct Adhesion {
    float c, norm;
    explicit Adhesion(float support, int dims = 3)
        : c(support), norm(0.007f / std::pow(support, dims == 2 ? 2.25f : 3.25f)) {}
    [[nodiscard]] float value(float r) const {
        if (r >= c || 2.0f * r <= c) return 0.0f;
        return norm * std::pow(std::max(-4.0f * r * r / c + 6.0f * r - 2.0f * c, 0.0f), 0.25f);
    }
};

}  // namespace tide::kernels
