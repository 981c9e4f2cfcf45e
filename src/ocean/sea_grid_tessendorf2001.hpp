#pragma once
/// \file
/// The far-field sea on a periodic grid by inverse FFT, after Tessendorf 2001, "Simulating
/// Ocean Water" (SIGGRAPH course notes): the surface is a sum of Fourier modes h̃(k, t) e^{ik·x}
/// over the grid's wave vectors k = 2π (m/Lx, n/Lz) (eq. 19), so one inverse 2D FFT gives η at
/// every grid point; the choppy displacement is the FFT of −i k/|k| h̃ (eq. 29) and the surface
/// velocity that of i ω-weighted modes (the linear field of ocean/sea.hpp at y = 0, with
/// finite depth's coth(kd)). Real fields are paired as F + iG into one complex transform.
///
/// The sea's components must lie on the grid's wave vectors (snapToGrid moves them there);
/// then the grid holds exactly the direct sum at its points (tests: within 1e-5 Hs; measured
/// ~1e-15 relative). FFTs: kissfft's C++ template (BSD-3, Debian's libkissfft-dev) in double.

#include <complex>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "ocean/sea.hpp"

namespace tide::ocean {

/// A periodic grid over [origin, origin + length) on x and z; point (i, j) is at
/// origin + (i Lx/Nx, j Lz/Nz), stored at index j Nx + i.
struct GridSpec {
    double lengthX = 0.0, lengthZ = 0.0;  ///< m
    int pointsX = 0, pointsZ = 0;         ///< ≥ 2 each
    glm::dvec2 origin{0.0};               ///< (x, z) of point (0, 0), m
};

/// `sea` with each component's wave vector moved to the nearest wave vector of `grid`
/// (ω from the dispersion relation again; amplitude and phase kept). Components that land on
/// k = 0 or on a Nyquist wave number (|m| = N/2), which the grid cannot carry, are dropped.
Sea snapToGrid(const Sea& sea, const GridSpec& grid);

/// A sea sampled at every interior wave vector of `grid`, as Tessendorf 2001 does for
/// rendering (every bin filled, not only those a discretise() sea lands on): for a spread
/// sea, each bin k gets the amplitude a = √(2 F(k) Δkx Δkz) of the directional wave-number
/// spectrum F(k) = S(ω) D(θ) c_g / k (S dω dθ = F k dk dθ, dω = c_g dk; Dean & Dalrymple 1991
/// for c_g), travelling along k, with a phase from the seed (std::mt19937_64, bins in storage
/// order). A long-crested sea or regular waves, whose D is a line, are snapToGrid(discretise).
/// Validates `def` (std::invalid_argument).
Sea gridSea(const OceanDef& def, const GridSpec& grid, double g = kGravity);

/// The sea's surface fields on a periodic grid at one time.
class SeaGrid {
public:
    /// Throws std::invalid_argument for a bad grid, or a component not on the grid's wave
    /// vectors (relative 1e-9), at k = 0 or at a Nyquist wave number.
    SeaGrid(const Sea& sea, GridSpec grid);
    ~SeaGrid();
    SeaGrid(SeaGrid&&) noexcept;
    SeaGrid& operator=(SeaGrid&&) noexcept;

    /// Fills every field for time t.
    void update(double t);

    [[nodiscard]] const GridSpec& grid() const { return grid_; }
    [[nodiscard]] glm::dvec2 position(int i, int j) const;
    /// η, m.
    [[nodiscard]] const std::vector<double>& elevation() const { return elevation_; }
    /// Choppy horizontal displacement of the surface (Sea::horizontalDisplacement), m.
    [[nodiscard]] const std::vector<double>& displacementX() const { return displacementX_; }
    [[nodiscard]] const std::vector<double>& displacementZ() const { return displacementZ_; }
    /// Linear velocity at still water (y = 0), with the sea's current: horizontal (u, w) and
    /// vertical v, m/s.
    [[nodiscard]] const std::vector<double>& velocityX() const { return velocityX_; }
    [[nodiscard]] const std::vector<double>& velocityY() const { return velocityY_; }
    [[nodiscard]] const std::vector<double>& velocityZ() const { return velocityZ_; }

private:
    // One component as the grid carries it: its bins (index of k and of −k) and, for each of
    // the three field pairs, its complex amplitudes there at t = 0 (see the .cpp).
    struct Mode {
        int bin, mirror;
        double omega;
        std::complex<double> plus[3], minus[3];
    };
    struct Transforms;
    void inverse2d(std::vector<std::complex<double>>& field);

    GridSpec grid_;
    std::vector<Mode> modes_;
    std::unique_ptr<Transforms> transforms_;
    std::vector<std::complex<double>> work_, line_, lineOut_;
    std::vector<double> elevation_, displacementX_, displacementZ_, velocityX_, velocityY_, velocityZ_;
    glm::dvec2 current_{0.0};  // the sea's uniform current, added to the velocities
};

}  // namespace tide::ocean
