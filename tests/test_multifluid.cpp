// Several fluids at once (issue 5): density-contrast SPH (Solenthaler & Pajarola 2008) in
// dfsph, pcisph and wcsph, layering by density, no gap at an interface, Rayleigh–Taylor,
// buoyancy, and dye diffusion between miscible materials.
//
// The worlds are thin boxes, three particle layers deep in z between walls, so each test runs
// in seconds: a 2D flow with the walls' boundary particles in front and behind. Not two:
// in a two-layer slab every particle touches both walls, and at the free surface the walls'
// boundary particles above the water push the top layer's two rows towards each other
// (nothing is above them on the fluid's side). In the 5:1 column drop two such mirror twins
// closed from 0.93 to 0.09 spacings within 0.07 s, and the density solve could not part them
// (the kernel's gradient vanishes at r → 0): whether its retaken steps then recovered was
// down to the sums' rounding (measured 2026-12-02, docs/performance.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/world.hpp>

namespace {

using namespace tide;

constexpr float kSpacing = 0.01f;

/// A box `width` × `height` × 3 spacings, walls all round.
World thinBox(float width, float height, const std::string& solver, float spacing = kSpacing) {
    WorldDef def;
    def.domainMax = {width, height, 3.0f * spacing};
    def.particleSpacing = spacing;
    def.solver.method = solver;
    def.threads = 1;
    return World(def);
}

MaterialIndex addFluid(World& world, const char* name, float density, float viscosity = 0.001f) {
    MaterialDef m;
    m.name = name;
    m.restDensity = density;
    m.viscosity = viscosity;
    return world.addMaterial(m);
}

void addBox(World& world, float x0, float y0, float x1, float y1, MaterialIndex material, float concentration = 0.0f) {
    BlockDef block;
    block.min = {x0, y0, 0.0f};
    block.max = {x1, y1, world.def().domainMax.z};
    block.material = material;
    block.concentration = concentration;
    ASSERT_EQ(world.addBlock(block), AddStatus::Added);
}

bool allFinite(const World& world) {
    const ParticleStore& p = world.particles();
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (!std::isfinite(p.position[i].x) || !std::isfinite(p.position[i].y) || !std::isfinite(p.velocity[i].x) ||
            !std::isfinite(p.density[i]))
            return false;
    return true;
}

std::vector<float> heightsOf(const World& world, MaterialIndex m) {
    std::vector<float> y;
    const ParticleStore& p = world.particles();
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (p.material[i] == m) y.push_back(p.position[i].y);
    return y;
}

float median(std::vector<float> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

/// Mean compression max(ρ − ρ0, 0)/ρ0 of one material's particles (the solvers' measure).
double meanCompression(const World& world, MaterialIndex m) {
    const ParticleStore& p = world.particles();
    const double rho0 = world.materials()[m].restDensity;
    double sum = 0.0;
    std::size_t n = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (p.material[i] == m) {
            sum += std::max(0.0, (p.density[i] - rho0) / rho0);
            ++n;
        }
    return sum / static_cast<double>(std::max<std::size_t>(n, 1));
}

struct Layering {
    std::vector<float> medians;       ///< per material, heaviest first
    std::vector<double> wrongSide;    ///< per interface: fraction of the two layers' particles on the wrong side, likewise
    std::vector<double> compression;  ///< per material, time-averaged over the last 0.5 s
    bool finite = true;
    std::uint32_t lost = 0;
};

/// Side-by-side columns of the given densities (heaviest first, each `columnWidth` wide and
/// `height` high) dropped into a box; they settle for `settle` s.
Layering dropColumns(const std::string& solver, const std::vector<float>& densities, float settle) {
    const float columnWidth = 0.1f, height = 0.2f;
    const float width = columnWidth * static_cast<float>(densities.size());
    World world = thinBox(width, 0.35f, solver);
    std::vector<MaterialIndex> materials;
    for (std::size_t k = 0; k < densities.size(); ++k)
        materials.push_back(addFluid(world, ("fluid " + std::to_string(k)).c_str(), densities[k]));
    for (std::size_t k = 0; k < densities.size(); ++k)
        addBox(world, columnWidth * static_cast<float>(k), 0.0f, columnWidth * static_cast<float>(k + 1), height, materials[k]);
    const std::uint32_t count = world.particles().size();
    // Each layer is `height`/n thick when settled: interface k lies at (k + 1)·height/n.
    const float layer = height / static_cast<float>(densities.size());
    auto addWrongSide = [&](std::vector<double>& sums) {
        for (std::size_t k = 0; k + 1 < densities.size(); ++k) {
            const float interface = layer * static_cast<float>(k + 1);
            std::size_t wrong = 0, total = 0;
            for (const float y : heightsOf(world, materials[k])) wrong += y > interface, ++total;
            for (const float y : heightsOf(world, materials[k + 1])) wrong += y < interface, ++total;
            sums[k] += static_cast<double>(wrong) / static_cast<double>(total);
        }
    };
    Layering out;
    world.advance(settle - 0.5, [&] { out.finite = out.finite && allFinite(world); });
    out.compression.assign(densities.size(), 0.0);
    out.wrongSide.assign(densities.size() - 1, 0.0);
    int samples = 0;
    // Averaged over the last 0.5 s: the settled interfaces still slosh (the 1000/200 one of the
    // three-material drop read 0.02–0.10 at half-second marks from 1.5 to 4 s), and one
    // instant samples the slosh's phase.
    world.advance(0.5, [&] {
        out.finite = out.finite && allFinite(world);
        for (std::size_t k = 0; k < densities.size(); ++k) out.compression[k] += meanCompression(world, materials[k]);
        addWrongSide(out.wrongSide);
        ++samples;
    });
    for (double& c : out.compression) c /= samples;
    for (double& w : out.wrongSide) w /= samples;
    out.lost = count - world.particles().size() + world.countEscapedParticles();
    for (const MaterialIndex m : materials) out.medians.push_back(median(heightsOf(world, m)));
    std::printf("%s columns", solver.c_str());
    for (const float d : densities) std::printf(" %.0f", d);
    std::printf(": medians");
    for (const float m : out.medians) std::printf(" %.4f", m);
    std::printf(" m, wrong side");
    for (const double w : out.wrongSide) std::printf(" %.3f", w);
    std::printf(", mean compression");
    for (const double c : out.compression) std::printf(" %.5f", c);
    std::printf(", lost %u\n", out.lost);
    return out;
}

void expectLayered(const Layering& l, double tolerance) {
    EXPECT_TRUE(l.finite);
    EXPECT_EQ(l.lost, 0u);
    for (std::size_t k = 0; k + 1 < l.medians.size(); ++k) EXPECT_LT(l.medians[k], l.medians[k + 1]) << "layer " << k;
    for (const double w : l.wrongSide) EXPECT_LT(w, 0.10);
    for (const double c : l.compression) EXPECT_LT(c, tolerance);
}

/// The pcisph and wcsph repeats of the dfsph (default solver) tests take 20–70 s each, over
/// the suite's budget: they run with TIDE_LONG_TESTS=1.
bool longTestsEnabled() { return std::getenv("TIDE_LONG_TESTS") != nullptr; }
#define TIDE_SKIP_UNLESS_LONG() \
    if (!longTestsEnabled()) GTEST_SKIP() << "a repeat on another solver: set TIDE_LONG_TESTS=1"

TEST(Multifluid, DfsphLayersDensityRatio25) { expectLayered(dropColumns("dfsph", {5000, 200}, 2.0f), 0.001); }
TEST(Multifluid, DfsphLayersDensityRatio5) { expectLayered(dropColumns("dfsph", {1000, 200}, 2.0f), 0.001); }
// Three layers settle later: after the first slump the 1000/200 interface sloshes back, and
// the fraction on its wrong side went 0.05 at 1.5 s, 0.10–0.105 at 2 s, 0.06–0.08 at 2.5 s,
// 0.02–0.06 at 3 s (slabs of two and three layers, temporary driver, 2026-12-02); at 2 s the
// test sampled the slosh's peak.
TEST(Multifluid, DfsphLayersThreeMaterials) { expectLayered(dropColumns("dfsph", {5000, 1000, 200}, 3.0f), 0.001); }
TEST(Multifluid, PcisphLayersDensityRatio25) {
    TIDE_SKIP_UNLESS_LONG();
    expectLayered(dropColumns("pcisph", {5000, 200}, 2.0f), 0.001);
}
TEST(Multifluid, PcisphLayersThreeMaterials) {
    TIDE_SKIP_UNLESS_LONG();
    expectLayered(dropColumns("pcisph", {5000, 1000, 200}, 3.0f), 0.001);
}
// wcsph has no solver tolerance: c = 10 × the free-fall speed keeps compression near 1 %.
TEST(Multifluid, WcsphLayersDensityRatio5) {
    TIDE_SKIP_UNLESS_LONG();
    expectLayered(dropColumns("wcsph", {1000, 200}, 2.0f), 0.01);
}
TEST(Multifluid, WcsphLayersDensityRatio25) {
    TIDE_SKIP_UNLESS_LONG();
    expectLayered(dropColumns("wcsph", {5000, 200}, 2.0f), 0.01);
}

/// Heavy under light at rest, settled 1 s. Spacing across the interface: from each heavy
/// particle whose nearest particle above it is light, the distance to that particle (and
/// from each light one whose nearest below is heavy, downwards). Bulk spacing: the edge of
/// the cube each particle of the layers' interiors fills, (m_i/ρ_i)^⅓ — the fluid's own
/// spacing at its density. (The nearest-neighbour distance in the bulk is not: dfsph
/// leaves the bulk a disordered packing whose nearest neighbour above sits at 0.89 of the
/// spacing while the interface rows stay flat at 0.99 of it, which read as an 11 % "gap".)
/// Returns across / bulk.
double interfaceGapRatio(const std::string& solver, float heavy, float light) {
    World world = thinBox(0.2f, 0.3f, solver);
    const MaterialIndex h = addFluid(world, "heavy", heavy);
    const MaterialIndex l = addFluid(world, "light", light);
    addBox(world, 0.0f, 0.0f, 0.2f, 0.1f, h);
    addBox(world, 0.0f, 0.1f, 0.2f, 0.2f, l);
    world.advance(1.0);
    EXPECT_TRUE(allFinite(world));
    const ParticleStore& p = world.particles();
    double across = 0.0, bulk = 0.0;
    int nAcross = 0, nBulk = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        const glm::vec3 xi = p.position[i];
        if (xi.x < 0.03f || xi.x > 0.17f) continue;  // away from the side walls
        const bool isHeavy = p.material[i] == h;
        const float side = isHeavy ? 1.0f : -1.0f;  // heavy looks up, light looks down
        float nearest = std::numeric_limits<float>::max();
        MaterialIndex of = p.material[i];
        for (std::uint32_t j = 0; j < p.size(); ++j) {
            if (side * (p.position[j].y - xi.y) <= 0.0f) continue;
            const float d = glm::length(xi - p.position[j]);
            if (d < nearest) {
                nearest = d;
                of = p.material[j];
            }
        }
        if (nearest > 2.0f * kSpacing) continue;  // the free surface
        const bool deep = isHeavy ? xi.y > 0.03f && xi.y < 0.07f : xi.y > 0.13f && xi.y < 0.17f;
        if (of != p.material[i]) {
            across += nearest;
            ++nAcross;
        } else if (deep) {
            bulk += std::cbrt(p.mass[i] / p.density[i]);
            ++nBulk;
        }
    }
    const double ratio = (across / nAcross) / (bulk / nBulk);
    std::printf("%s interface %.0f/%.0f: spacing across %.5f m (%d particles), bulk %.5f m (%d), ratio %.3f\n",
                solver.c_str(), heavy, light, across / nAcross, nAcross, bulk / nBulk, nBulk, ratio);
    EXPECT_GT(nAcross, 10);
    EXPECT_GT(nBulk, 20);
    return ratio;
}

void expectNoGap(const char* solver) {
    for (const float light : {200.0f, 1000.0f}) {
        const double ratio = interfaceGapRatio(solver, light == 1000.0f ? 5000.0f : 1000.0f, light);
        EXPECT_LT(std::abs(ratio - 1.0), 0.10) << solver << " " << light;
    }
}

TEST(Multifluid, NoGapAtAFlatInterface) { expectNoGap("dfsph"); }
TEST(Multifluid, NoGapAtAFlatInterfaceOtherSolvers) {
    TIDE_SKIP_UNLESS_LONG();
    expectNoGap("pcisph");
    expectNoGap("wcsph");
}

// Rayleigh–Taylor and the discs run wcsph: dfsph and pcisph with a density contrast diverge
// when heavy fluid lies over light in this thin box (the density solve's error grows from
// the second step and the 2:1 box blows up at 0.02 s, measured) — an open problem. dfsph
// also blows up in the equal-density box, which water fills to the lid (no free surface):
// the divergence guard stopped it at step 11 (measured after the merge with the guard).

/// Heavy over light in a box 0.2 m wide and 0.4 m tall, the interface at mid-height with a
/// one-spacing step seeding the longest mode, at 2 cm (10 particles across: the instability
/// grows on the box's scale, and 1 cm took 70 s a run). Returns the fraction of the upper fluid's
/// particles below the lower quarter line after `duration`, and prints when they first got there.
double rayleighTaylor(float upper, float lower, double duration) {
    World world = thinBox(0.2f, 0.4f, "wcsph", 2.0f * kSpacing);
    const MaterialIndex top = addFluid(world, "upper", upper);
    const MaterialIndex bottom = addFluid(world, "lower", lower);
    const float step = world.def().particleSpacing;
    addBox(world, 0.0f, 0.0f, 0.1f, 0.2f + step, bottom);
    addBox(world, 0.1f, 0.0f, 0.2f, 0.2f - step, bottom);
    addBox(world, 0.0f, 0.2f + step, 0.1f, 0.4f, top);
    addBox(world, 0.1f, 0.2f - step, 0.2f, 0.4f, top);
    double reached = -1.0;
    double fraction = 0.0;
    bool finite = true;
    world.advance(duration, [&] {
        const auto y = heightsOf(world, top);
        const auto below = std::count_if(y.begin(), y.end(), [](float v) { return v < 0.1f; });
        fraction = static_cast<double>(below) / static_cast<double>(y.size());
        if (reached < 0.0 && below > 0) reached = world.time();
        finite = finite && allFinite(world);
    });
    EXPECT_TRUE(finite);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    std::printf("Rayleigh-Taylor %.0f over %.0f: upper fluid first below y = 0.1 m at %.3f s, %.1f %% there after %.1f s\n",
                upper, lower, reached, 100.0 * fraction, duration);
    return fraction;
}

// Layers one spacing thick, water and a fluid five times lighter in turn, so that every layer
// is an interface and every interface is heavy over light. Density solves diverge early on and
// dfsph retakes the step at half its length, again and again. It used to shorten the time over
// which the retaken step removes the compression already there by as much, so the velocities
// that removal takes grew as 1/Δt: at Δt = 1 µs the water reached 7,300 m/s and the run
// diverged at 5 ms. The retaken step keeps the drift time of the step it replaces (measured:
// max speed 3.35 m/s over 0.15 s).
TEST(Multifluid, DfsphThinAlternatingLayersHold) {
    WorldDef def;
    def.domainMax = {0.1f, 0.3f, 0.1f};
    def.particleSpacing = kSpacing;
    def.solver.method = "dfsph";
    def.threads = 1;
    World world(def);
    const MaterialIndex water = addFluid(world, "water", 1000.0f, 0.03f);
    const MaterialIndex light = addFluid(world, "light", 200.0f, 0.03f);
    for (int layer = 0; layer < 20; ++layer) {
        const float y0 = kSpacing * static_cast<float>(layer);
        addBox(world, 0.0f, y0, 0.1f, y0 + kSpacing, layer % 2 == 0 ? light : water);
    }
    float fastest = 0.0f;
    EXPECT_NO_THROW(world.advance(0.15, [&] { fastest = std::max(fastest, world.stats().maxSpeed); }));
    EXPECT_TRUE(allFinite(world));
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    std::printf("dfsph, 20 alternating layers 1000/200 one spacing thick: max speed %.2f m/s over %.3f s in %llu steps "
                "(shortest %.1e s)\n",
                fastest, world.time(), static_cast<unsigned long long>(world.stats().steps), world.stats().dtMin);
    // The light fluid's buoyancy in water, 4 g, acting unopposed for the whole 0.15 s: 5.9 m/s.
    EXPECT_LT(fastest, 5.9f);
}

TEST(Multifluid, RayleighTaylorHeavyOverLightOverturns) {
    EXPECT_GT(rayleighTaylor(2000.0f, 1000.0f, 1.5), 0.2);
}

TEST(Multifluid, RayleighTaylorEqualDensitiesStayPut) {
    EXPECT_EQ(rayleighTaylor(1000.0f, 1000.0f, 1.5), 0.0);
}

/// A disc (in the thin box: a cylinder) of `density` and radius 0.03 m, centred at mid-depth
/// of a 0.2 m water column, built from one-row blocks on the water's lattice. Returns the
/// disc's median height after `duration`.
float releaseDisc(float density, double duration) {
    World world = thinBox(0.2f, 0.3f, "wcsph");
    const MaterialIndex water = addFluid(world, "water", 1000.0f);
    const MaterialIndex disc = addFluid(world, "disc", density);
    const float cx = 0.1f, cy = 0.1f, radius = 0.03f, depth = 0.2f;
    for (int row = 0; row < static_cast<int>(std::lround(depth / kSpacing)); ++row) {
        const float y0 = kSpacing * static_cast<float>(row), y1 = y0 + kSpacing;
        const float dy = y0 + 0.5f * kSpacing - cy;
        const float half = std::abs(dy) < radius ? std::sqrt(radius * radius - dy * dy) : 0.0f;
        // Whole lattice columns whose centres lie inside the disc.
        const int first = static_cast<int>(std::ceil((cx - half) / kSpacing - 0.5f));
        const int last = static_cast<int>(std::floor((cx + half) / kSpacing - 0.5f));
        if (last < first) {
            addBox(world, 0.0f, y0, 0.2f, y1, water);
            continue;
        }
        const float x0 = kSpacing * static_cast<float>(first), x1 = kSpacing * static_cast<float>(last + 1);
        addBox(world, 0.0f, y0, x0, y1, water);
        addBox(world, x0, y0, x1, y1, disc);
        addBox(world, x1, y0, 0.2f, y1, water);
    }
    EXPECT_EQ(world.particles().size() % 2, 0u);
    const float start = median(heightsOf(world, disc));
    world.advance(duration);
    EXPECT_TRUE(allFinite(world));
    EXPECT_EQ(world.countEscapedParticles(), 0u);
    const float end = median(heightsOf(world, disc));
    std::printf("disc of %.0f kg/m3 in water %.2f m deep: median height %.4f m -> %.4f m after %.1f s\n", density, depth,
                start, end, duration);
    return end;
}

TEST(Multifluid, LightDiscRisesToTheSurface) {
    // Surfaced: its median within 3 spacings of the water's surface (0.2 m, a little higher
    // once the disc floats in it).
    EXPECT_GT(releaseDisc(500.0f, 1.2), 0.2f - 3.0f * kSpacing);
}

TEST(Multifluid, HeavyDiscSinks) {
    // On the floor: its median within a radius and 2 spacings of it.
    EXPECT_LT(releaseDisc(3000.0f, 1.0), 0.03f + 2.0f * kSpacing);
}

/// Dyed water (c = 1) in a strip in the middle of clear water, miscible with diffusivity D.
TEST(Multifluid, MiscibleDyeSpreadsAndIsConserved) {
    const float diffusivity = 2e-4f;
    World world = thinBox(0.3f, 0.2f, "dfsph");
    const MaterialIndex clear = addFluid(world, "water", 1000.0f);
    const MaterialIndex dyed = addFluid(world, "red water", 1000.0f);
    MaterialPairDef pair;
    pair.a = clear;
    pair.b = dyed;
    pair.miscible = true;
    pair.diffusivity = diffusivity;
    world.setMaterialPair(pair);
    addBox(world, 0.0f, 0.0f, 0.13f, 0.1f, clear);
    addBox(world, 0.13f, 0.0f, 0.17f, 0.1f, dyed, 1.0f);
    addBox(world, 0.17f, 0.0f, 0.3f, 0.1f, clear);
    // Σ m c x² / Σ m c − x̄²: grows by 2 D t along x while the dye is clear of the walls.
    const auto variance = [&] {
        const ParticleStore& p = world.particles();
        double m = 0.0, mx = 0.0, mxx = 0.0;
        for (std::uint32_t i = 0; i < p.size(); ++i) {
            const double w = static_cast<double>(p.mass[i]) * p.concentration[i];
            m += w;
            mx += w * p.position[i].x;
            mxx += w * p.position[i].x * p.position[i].x;
        }
        return mxx / m - (mx / m) * (mx / m);
    };
    const double mean0 = world.meanConcentration();
    const double var0 = variance();
    double worst = 0.0;
    float minC = 1.0f, maxC = 0.0f;
    const double duration = 2.0;
    world.advance(duration, [&] {
        worst = std::max(worst, std::abs(world.meanConcentration() - mean0) / mean0);
    });
    for (const float c : world.particles().concentration) {
        minC = std::min(minC, c);
        maxC = std::max(maxC, c);
    }
    const double growth = variance() - var0;
    std::printf("dye: mean %.6f, largest relative drift %.2e; x variance %.3e -> %.3e m^2 (+%.3e, 2Dt = %.3e); c in [%.4f, %.4f]\n",
                mean0, worst, var0, variance(), growth, 2.0 * diffusivity * duration, minC, maxC);
    EXPECT_LT(worst, 1e-6);
    EXPECT_NEAR(growth, 2.0 * diffusivity * duration, 0.2 * 2.0 * diffusivity * duration);
    EXPECT_GE(minC, 0.0f);
    EXPECT_LE(maxC, 1.0f);
    EXPECT_LT(maxC, 0.9f) << "the strip's centre has lost dye";
}

TEST(Multifluid, ImmiscibleDyeStaysPut) {
    World world = thinBox(0.2f, 0.2f, "dfsph");
    const MaterialIndex a = addFluid(world, "water", 1000.0f);
    const MaterialIndex b = addFluid(world, "red water", 1000.0f);
    MaterialPairDef pair{a, b, false, 1e-4f};
    EXPECT_THROW(world.setMaterialPair(pair), std::invalid_argument);  // diffusivity without miscible
    pair.diffusivity = 0.0f;
    world.setMaterialPair(pair);
    addBox(world, 0.0f, 0.0f, 0.1f, 0.1f, a);
    addBox(world, 0.1f, 0.0f, 0.2f, 0.1f, b, 1.0f);
    world.advance(0.3);
    for (std::uint32_t i = 0; i < world.particles().size(); ++i)
        EXPECT_EQ(world.particles().concentration[i], world.particles().material[i] == b ? 1.0f : 0.0f);
}

TEST(Multifluid, BadPairsAreRejectedByName) {
    World world = thinBox(0.2f, 0.2f, "dfsph");
    addFluid(world, "water", 1000.0f);
    const auto message = [&](const MaterialPairDef& pair) {
        try {
            world.setMaterialPair(pair);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message({0, 3, true, 0.0f}).find("materialPair.materials"), std::string::npos);
    EXPECT_NE(message({0, 0, false, -1.0f}).find("materialPair.diffusivity"), std::string::npos);
    EXPECT_NE(message({0, 0, false, std::nanf("")}).find("materialPair.diffusivity"), std::string::npos);
    EXPECT_NE(message({0, 0, true, 0.0f}).find("materialPair.miscible"), std::string::npos);
}

}  // namespace
