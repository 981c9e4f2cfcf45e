// Plane Poiseuille flow: a viscous fluid between two walls (y = 0 and y = H), periodic in x
// and z, driven along x by a body force f, reaches u(y) = (f / 2ν) y (H − y). This checks
// the physical viscosity (its value, not only its presence), the no-slip walls and the
// periodic axes together.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <tide/world.hpp>

namespace {

using namespace tide;

struct Profile {
    std::vector<double> y, measured, analytic;
    double uMax = 0.0;           ///< analytic centre-line speed
    double maxError = 0.0;       ///< max |measured − analytic| over the bins, / uMax
    double maxCrossFlow = 0.0;   ///< largest mean |v_y|, |v_z| of a bin, / uMax
    std::uint32_t lost = 0;
};

/// The steady profile of `solver` with viscosity model `viscosity`: H = 0.1 m, 16 particles
/// across, a tile 6 × 6 spacings in x and z; ν = 0.01 m²/s, f = 0.8 m/s² (u_max = 0.1 m/s,
/// Re = u_max H / ν = 1). The slowest transient decays as 1.03 exp(−π² ν t / H²): after
/// 0.5 s it is below 0.8 % of u_max. The profile is then averaged over 0.05 s in bins one
/// spacing thick, centred on the fluid's lattice layers.
Profile poiseuille(const std::string& solver, const std::string& viscosity) {
    const int bins = 16;
    const float H = 0.1f, s = H / static_cast<float>(bins), tile = 6.0f * s, f = 0.8f, rho = 1000.0f, nu = 0.01f;
    WorldDef def;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {tile, H, tile};
    def.periodic = {true, false, true};
    def.gravity = {f, 0.0f, 0.0f};
    def.particleSpacing = s;
    def.threads = 1;  // ~1000 particles: waking a second thread for each loop costs more than it gains
    def.solver.method = solver;
    def.solver.viscosity = viscosity;
    def.solver.xsph = 0.0f;  // only the physical viscosity
    World world(def);
    world.addMaterial(MaterialDef{"syrup", rho, nu * rho, {1, 1, 1}});
    EXPECT_EQ(world.addBlock({def.domainMin, def.domainMax, {0, 0, 0}, 0}), AddStatus::Added);
    const std::uint32_t n = world.particles().size();
    world.advance(0.5);

    std::vector<double> sum(bins, 0.0), cross(bins, 0.0), count(bins, 0.0);
    for (int sample = 0; sample < 10; ++sample) {
        world.advance(0.005);
        const ParticleStore& p = world.particles();
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const int bin = std::clamp(static_cast<int>(p.position[i].y / s), 0, bins - 1);
            sum[bin] += p.velocity[i].x;
            cross[bin] += std::max(std::abs(p.velocity[i].y), std::abs(p.velocity[i].z));
            count[bin] += 1.0;
        }
    }
    Profile out;
    out.uMax = f * H * H / (8.0 * nu);
    out.lost = n - world.particles().size() + world.countEscapedParticles();
    std::printf("%s/%s: y [m], u measured, u analytic [m/s], error / u_max\n", solver.c_str(), viscosity.c_str());
    for (int b = 0; b < bins; ++b) {
        const double y = (b + 0.5) * s;
        const double u = sum[b] / std::max(count[b], 1.0);
        const double exact = f / (2.0 * nu) * y * (H - y);
        out.y.push_back(y);
        out.measured.push_back(u);
        out.analytic.push_back(exact);
        out.maxError = std::max(out.maxError, std::abs(u - exact) / out.uMax);
        out.maxCrossFlow = std::max(out.maxCrossFlow, cross[b] / std::max(count[b], 1.0) / out.uMax);
        std::printf("  %.4f  %.5f  %.5f  %+.3f\n", y, u, exact, (u - exact) / out.uMax);
    }
    const WorldStats& stats = world.stats();
    std::printf("%s/%s: max error %.2f %% of u_max, cross flow %.2f %%, %llu steps, %.1f pressure iterations per step\n",
                solver.c_str(), viscosity.c_str(), 100.0 * out.maxError, 100.0 * out.maxCrossFlow,
                static_cast<unsigned long long>(stats.steps),
                static_cast<double>(stats.pressureIterationsSum) / static_cast<double>(stats.steps));
    return out;
}

// The acceptance case (measured: max error ~1 % of u_max). Walls with v_b = 0 instead of
// Adami's mirrored velocity left a slip of ~10 %; Monaghan 2005's form gives ~22 % (its
// shear response on the support-2 lattice is 0.71 ν∂²u/∂y², see test_viscosity.cpp).
TEST(Poiseuille, DfsphMorrisReachesTheParabolicProfile) {
    const Profile p = poiseuille("dfsph", "morris");
    EXPECT_EQ(p.lost, 0u);
    EXPECT_LT(p.maxError, 0.10);
}

TEST(Poiseuille, WcsphMorrisReachesTheParabolicProfile) {
    const Profile p = poiseuille("wcsph", "morris");
    EXPECT_EQ(p.lost, 0u);
    EXPECT_LT(p.maxError, 0.10);
}

// Müller's viscosity kernel: ~6 % (its Laplacian is 2 % low on the lattice; the classic
// solver's weakly compressible noise does the rest).
TEST(Poiseuille, ClassicMullerReachesTheParabolicProfile) {
    const Profile p = poiseuille("classic", "muller");
    EXPECT_EQ(p.lost, 0u);
    EXPECT_LT(p.maxError, 0.10);
}

}  // namespace
