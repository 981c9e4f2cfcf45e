// The far field's surface as meshes see it (ocean/sea_surface.hpp): at a fine spacing it is
// the sea's own elevation, choppy displacement and slope; components too short for a mesh's
// spacing fade out; any thread count gives the same points.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "ocean/sea.hpp"
#include "ocean/sea_surface.hpp"

namespace tide::ocean {
namespace {

OceanDef directionalSea() {
    OceanDef def;
    def.depth = 0.7;
    def.waves.type = OceanWavesDef::Type::Jonswap;
    def.waves.hs = 0.1;
    def.waves.tp = 1.5;
    def.waves.spreading = 10.0;
    def.waves.direction = 30.0;
    def.waves.components = 24;
    def.waves.directions = 4;
    def.waves.seed = 3;
    return def;
}

TEST(SeaSurface, FineSamplesAreTheSeasElevationDisplacementAndSlope) {
    const Sea sea = Sea::fromDef(directionalSea());
    std::vector<glm::dvec2> rest;
    for (int i = 0; i < 50; ++i) rest.emplace_back(-3.0 + 0.37 * i, 2.0 - 0.21 * i);
    const std::vector<float> fine(rest.size(), 1e-4f);  // every component fully
    SurfaceSampling sampling;
    sampling.time = 4.3;
    sampling.stillWaterY = 0.7;
    std::vector<SurfacePoint> out(rest.size());
    sampleSurface(sea, rest, fine, sampling, out);
    const double h = 1e-5;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const double x = rest[i].x, z = rest[i].y, t = sampling.time;
        const glm::dvec2 d = sea.horizontalDisplacement(x, z, t);
        EXPECT_NEAR(out[i].position.y, 0.7 + sea.elevation(x, z, t), 1e-6);
        EXPECT_NEAR(out[i].position.x, x + d.x, 1e-5);
        EXPECT_NEAR(out[i].position.z, z + d.y, 1e-5);
        // the normal from central differences of η
        const double sx = (sea.elevation(x + h, z, t) - sea.elevation(x - h, z, t)) / (2 * h);
        const double sz = (sea.elevation(x, z + h, t) - sea.elevation(x, z - h, t)) / (2 * h);
        const double norm = std::sqrt(1.0 + sx * sx + sz * sz);
        EXPECT_NEAR(out[i].normal.x, -sx / norm, 1e-4);
        EXPECT_NEAR(out[i].normal.y, 1.0 / norm, 1e-4);
        EXPECT_NEAR(out[i].normal.z, -sz / norm, 1e-4);
    }
}

TEST(SeaSurface, ComponentsTooShortForTheSpacingFadeAndTheRampScales) {
    // Two regular-like components: 1 m and 0.1 m long, on deep water.
    const double g = kGravity, depth = 10.0;
    const auto component = [&](double length, double a) {
        const double k = 2.0 * std::numbers::pi / length;
        return WaveComponent{a, std::sqrt(g * k * std::tanh(k * depth)), k, 0.0, 0.0};
    };
    const Sea sea({component(1.0, 0.05), component(0.1, 0.01)}, depth);
    const std::vector<glm::dvec2> rest{{0.0, 0.0}};  // both crests there at t = 0
    SurfaceSampling sampling;
    sampling.choppy = false;
    std::vector<SurfacePoint> out(1);
    // 0.01 m: 10 samples a short wavelength, both whole
    sampleSurface(sea, rest, std::vector<float>{0.01f}, sampling, out);
    EXPECT_NEAR(out[0].position.y, 0.06, 1e-6);
    // 0.05 m: two samples a short wavelength (kΔ = π), the long one whole (kΔ = 0.31)
    sampleSurface(sea, rest, std::vector<float>{0.05f}, sampling, out);
    EXPECT_NEAR(out[0].position.y, 0.05, 1e-6);
    // 0.0375 m: kΔ = 3π/4 for the short one, half way: weight ½
    sampleSurface(sea, rest, std::vector<float>{0.0375f}, sampling, out);
    EXPECT_NEAR(out[0].position.y, 0.055, 1e-5);
    sampling.ramp = 0.25;
    sampleSurface(sea, rest, std::vector<float>{0.01f}, sampling, out);
    EXPECT_NEAR(out[0].position.y, 0.015, 1e-6);
}

TEST(SeaSurface, SameForAnyThreadCountAndRefusesMismatchedSizes) {
    const Sea sea = Sea::fromDef(directionalSea());
    std::vector<glm::dvec2> rest;
    std::vector<float> spacing;
    for (int i = 0; i < 3000; ++i) {
        rest.emplace_back(0.01 * i, 0.003 * i);
        spacing.push_back(0.001f * static_cast<float>(i % 300));
    }
    std::vector<SurfacePoint> one(rest.size()), two(rest.size());
    sampleSurface(sea, rest, spacing, {}, one, 1);
    sampleSurface(sea, rest, spacing, {}, two, 2);
    for (std::size_t i = 0; i < rest.size(); ++i) {
        EXPECT_EQ(one[i].position, two[i].position);
        EXPECT_EQ(one[i].normal, two[i].normal);
    }
    std::vector<SurfacePoint> short_(rest.size() - 1);
    EXPECT_THROW(sampleSurface(sea, rest, spacing, {}, short_), std::invalid_argument);
}

}  // namespace
}  // namespace tide::ocean
