#pragma once
/// \file
/// How the pressure solves' Jacobi weights scale with the kernel's support.
///
/// A Jacobi step κ_i += ω α_i r_i (dfsph's α_i, pcisph's δ_i: the inverse of the diagonal)
/// on a filled neighbourhood multiplies a pressure mode of wave vector k by 1 − ω G(k), with
///   G(k) = |Σ_r sin(k·r) ∇W(r)|² / Σ_r |∇W(r)|²
/// over the neighbours r of a lattice site (the density change of the pressure force
/// −Σ_j m_j (κ_i/ρ_i + κ_j/ρ_j) ∇W_ij, Fourier-transformed on the lattice). The step is stable
/// while ω max_k G < 2 (2(1 + β) with heavy-ball momentum β). max G grows with the number of
/// neighbours: 2.8 on the simple cubic lattice at the default support of 2 spacings, 7.5 at 3,
/// 17.6 at 4. The weights the solves were tuned with at 2 spacings (dfsph's density solve ½,
/// its divergence solve 1) overshoot beyond ~2.7: at 3 spacings a tank at rest blew up within
/// two steps. So wider supports scale the weights by max G(2)/max G(s), that of the cubic
/// spline at 2 spacings; Wendland C2's max G is a little lower (2.6 at 2 spacings, 6.2 at 3).

#include <tide/defs.hpp>

namespace tide {

/// max_k G(k) on the simple cubic lattice of unit spacing (the square lattice in 2D), the
/// kernel `shape` with support `supportRatio` (in spacings), k over the Brillouin zone on a 13³ grid.
[[nodiscard]] float latticeJacobiGain(float supportRatio, KernelShape shape = KernelShape::CubicSpline,
                                      int dimensions = 3);

/// The factor for Jacobi weights tuned with the cubic spline at the default support (2 spacings):
/// min(1, latticeJacobiGain(2) / latticeJacobiGain(supportRatio, shape)); exactly 1 for the
/// cubic spline up to 2 spacings. In 2D both gains are the square lattice's.
[[nodiscard]] float jacobiWeightScale(float supportRatio, KernelShape shape = KernelShape::CubicSpline,
                                      int dimensions = 3);

/// jacobiWeightScale for a solver's steps, computed again only when the support changes.
class JacobiWeightScale {
public:
    [[nodiscard]] float operator()(float supportRatio, KernelShape shape, int dimensions = 3) {
        if (supportRatio != ratio_ || shape != shape_ || dimensions != dimensions_) {
            ratio_ = supportRatio;
            shape_ = shape;
            dimensions_ = dimensions;
            scale_ = jacobiWeightScale(supportRatio, shape, dimensions);
        }
        return scale_;
    }

private:
    float ratio_ = -1.0f, scale_ = 1.0f;
    int dimensions_ = 3;
    KernelShape shape_ = KernelShape::CubicSpline;
};

}  // namespace tide
