#pragma once
/// \file
/// The far field's surface and velocity on a lattice over the coupling bands, evaluated once
/// per time and interpolated to the particles there (issue 43's cost: a direct sum over every
/// component for every particle of a band, every step, took 40 % of a step).
///
/// Columns stand at origin + (i, j)·step in x–z; each holds η and, on levels of the
/// Wheeler-stretched height y' = −d + l·d/L (l = −1 … L + 1: one level beyond the floor and the
/// surface, so the cubic interpolation needs no one-sided stencil there; the linear profiles
/// cosh/sinh continue analytically), the velocity of ocean/sea.hpp. In stretched coordinates
/// the profiles do not depend on η (Wheeler 1970), so the lattice is fixed in space and only
/// its values change with time. A Stokes wave (Sea::kinematics() Truncated) is read
/// unstretched: its levels run from the floor to the highest crest, Σ a, instead.
///
/// The direct sum at a column is cheap: the phase factor e^{i(kx x + kz z)} is the product of
/// tables along x and z (no transcendental per column), times e^{i(φ − ωt)} once per
/// component; the vertical profiles are tables per level. Particles read the lattice by
/// Catmull–Rom (cubic, interpolating) weights in x, z and y' (Catmull & Rom 1974).
///
/// The short components that the lattice cannot hold (a wavelength under a few steps) are
/// smoothed: tests/test_ocean_zones.cpp measures the error against the direct sum.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "ocean/sea.hpp"

namespace tide::ocean {

/// Where a lattice's columns are.
struct LatticeSpec {
    glm::dvec2 origin{0.0};  ///< (x, z) of column (0, 0), sea coordinates, m
    double step = 0.0;       ///< between columns, m (> 0)
    int columnsX = 0, columnsZ = 0;  ///< ≥ 4 each (a cubic stencil)
    int levels = 0;          ///< L: the water column is cut into L layers (≥ 2)
    /// Columns that are evaluated (columnsX · columnsZ, index j·columnsX + i; empty: all).
    /// Only these are stored; one that is not reads as still water.
    std::vector<std::uint8_t> used;
};

/// A sea's η and velocity on a lattice at one time.
class SeaLattice {
public:
    /// Throws std::invalid_argument for a bad spec.
    SeaLattice(const Sea& sea, LatticeSpec spec);

    /// Evaluates every used column at time t (parallelFor on `threads`: the same values for
    /// any count); with `rates`, also the fields' time derivatives (for blend()).
    void update(double t, int threads = 1, bool rates = false);
    /// The fields at time t between two lattices of the same spec updated with rates at
    /// ta < tb (t in [ta, tb]), by the cubic Hermite interpolant in time: an update's sums over
    /// every component every few steps, and this cheap pass at every step. Its error for a
    /// component of frequency ω is about (ω (tb − ta))⁴/384 of its amplitude.
    void blend(const SeaLattice& a, const SeaLattice& b, double t, int threads = 1);
    /// The time of the last update (NaN before the first).
    [[nodiscard]] double time() const { return time_; }
    [[nodiscard]] const LatticeSpec& spec() const { return spec_; }

    /// η at (x, z), m (sea coordinates).
    [[nodiscard]] double elevation(double x, double z) const;
    /// The velocity at (x, y, z), y from still water, Wheeler-stretched as Sea::sample; above
    /// the surface the surface's velocity, below the floor the floor's.
    [[nodiscard]] glm::dvec3 velocity(const glm::dvec3& point) const;

private:
    struct Stencil {
        int first;     // index of the first of 4 nodes
        double w[4];   // Catmull–Rom weights
    };
    [[nodiscard]] Stencil horizontal(double coordinate, double origin, int count) const;
    [[nodiscard]] std::int32_t slotAt(int i, int j) const {
        return slot_[static_cast<std::size_t>(j) * static_cast<std::size_t>(spec_.columnsX) + static_cast<std::size_t>(i)];
    }

    LatticeSpec spec_;
    double depth_;
    Stretching kinematics_;  // the sea's: Wheeler, or Truncated for a Stokes wave
    double top_ = 0.0;       // the highest level's y above still water (Truncated), m
    double levelStep_ = 0.0; // between levels, m
    glm::dvec2 current_;     // the sea's uniform current (x, z), m/s
    int levelCount_;  // L + 3
    std::size_t components_;
    // Per component: amplitude, ω, phase; tables e^{i kx x_i} (columnsX × N), e^{i kz z_j}.
    std::vector<double> amplitude_, omega_, phase_;
    std::vector<double> cosX_, sinX_, cosZ_, sinZ_;
    // Per component and level (N × levelCount_): the velocity profiles a ω cosh/sinh ratios,
    // the horizontal one along x and along z.
    std::vector<float> profileX_, profileZ_, profileY_;
    // The used columns (their indices j·columnsX + i), and the slot of each column among
    // them (−1: not used).
    std::vector<std::uint32_t> active_;
    std::vector<std::int32_t> slot_;
    // The fields per used column: η, and the velocity (x, y, z) on each level, levels
    // contiguous: a particle's stencil reads 16 runs of 12 floats (float: the interpolation's
    // error is far above float's rounding).
    std::vector<float> elevation_, velocity_;
    std::vector<float> elevationRate_, velocityRate_;  // ∂/∂t, after update(t, _, true)
    double time_;
};

}  // namespace tide::ocean
