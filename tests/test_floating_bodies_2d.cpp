// Floating bodies in 2D worlds (prisms one metre wide, as the loads are per metre): the
// sinking cylinder of Moyo & Greenhow 2000 against their experiment and Fekken's 2004
// solution, and bad 2D bodies refused.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <tide/world.hpp>

namespace {

using namespace tide;

// The setup of floating_cylinder_sinking_*.csv (/work/shared/validation, copied to
// validation/data): R = 1 m, relative density 1.2, released from rest with its centre on the
// still-water line of water 14 m deep, the domain 10 m wide and periodic across. At R/10.
TEST(FloatingBodies2D, ASinkingCylinderFollowsTheExperimentAndTheReference) {
    const double R = 1.0, depth = 14.0, g = 9.81;
    WorldDef def;
    def.dimensions = 2;
    def.domainMin = {-5.0f, 0.0f, 0.0f};
    def.domainMax = {5.0f, static_cast<float>(depth + 2.0 * R), 0.0f};
    def.periodic = {true, false, false};
    def.particleSpacing = static_cast<float>(R / 10.0);
    def.threads = 1;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef cylinder;
    cylinder.shape = ObstacleDef::Shape::Circle;
    cylinder.center = {0.0f, static_cast<float>(depth), 0.0f};
    cylinder.radius = static_cast<float>(R);
    cylinder.name = "cylinder";
    BodyDynamicsDef body;
    body.density = 1200.0;
    cylinder.dynamics = body;
    world.addObstacle(cylinder);  // first: the water fills around it
    BlockDef water;
    water.min = {-5.0f, 0.0f, 0.0f};
    water.max = {5.0f, static_cast<float>(depth), 0.0f};
    world.addBlock(water);
    // The 14 m column falls onto its own pressure and rings for about 1.2 s: released after 0.5 s
    // the cylinder fell freely (the water had dropped away from it) and bounced off it.
    world.settle(2.0);  // the body held
    const BodyState start = world.bodies().at(0);
    EXPECT_EQ(start.position.y, depth) << "held while the water settles";
    // Displacement / R at t √(g/R) = 1, 2, 3: Fekken 2004 and Moyo & Greenhow 2000, read off
    // their tables by linear interpolation. Acceptance: within 0.1 R of the band between them.
    const double fekken[3] = {-0.1979, -0.6492, -1.1663}, experiment[3] = {-0.1539, -0.6572, -1.2920};
    for (int k = 1; k <= 3; ++k) {
        world.advance(k * std::sqrt(R / g) - world.time());
        const BodyState b = world.bodies().at(0);
        const double d = (b.position.y - start.position.y) / R;
        const double lo = std::min(fekken[k - 1], experiment[k - 1]), hi = std::max(fekken[k - 1], experiment[k - 1]);
        const double outside = std::max({0.0, lo - d, d - hi});
        std::printf("t* = %d: displacement %.4f R (band %.4f..%.4f, %.4f R outside), velocity %.4f sqrt(gR), x %.2e m\n",
                    k, d, lo, hi, outside, b.velocity.y / std::sqrt(g * R), b.position.x);
        EXPECT_LE(outside, 0.1) << "t* = " << k;
        EXPECT_NEAR(b.position.x, 0.0, 0.02 * R) << "it sinks straight down";
        EXPECT_EQ(b.position.z, 0.0) << "in the plane";
    }
}

// A 2D body is a box or a circle turning about z; the rest is refused naming the field.
TEST(FloatingBodies2D, BadPlanarBodiesAreRefusedNamingTheField) {
    WorldDef def;
    def.dimensions = 2;
    def.domainMax = {1.0f, 1.0f, 0.0f};
    World world(def);
    world.addMaterial(MaterialDef{});
    const auto refusal = [&](ObstacleDef o) {
        try {
            world.addObstacle(o);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    BodyDynamicsDef body;
    body.density = 500.0;
    ObstacleDef polygon;
    polygon.shape = ObstacleDef::Shape::Polygon;
    polygon.polygon = {{0.4f, 0.4f}, {0.6f, 0.4f}, {0.5f, 0.6f}};
    polygon.dynamics = body;
    EXPECT_NE(refusal(polygon).find("obstacle.dynamic: a polygon cannot be a floating body"), std::string::npos);
    ObstacleDef box;
    box.min = {0.4f, 0.4f, 0.0f};
    box.max = {0.6f, 0.6f, 0.0f};
    BodyDynamicsDef heave = body;
    heave.freeAxes = {"y", "rx"};
    box.dynamics = heave;
    EXPECT_NE(refusal(box).find("obstacle.constraint.free[1]: a 2D body moves in x, y and rz only, got \"rx\""),
              std::string::npos);
    BodyDynamicsDef tumbling = body;
    tumbling.angularVelocity = {1.0f, 0.0f, 0.0f};
    box.dynamics = tumbling;
    EXPECT_NE(refusal(box).find("obstacle.angular_velocity: a 2D body turns about z only"), std::string::npos);
    EXPECT_TRUE(world.bodies().empty());
    box.dynamics = body;
    world.addObstacle(box);
    ASSERT_EQ(world.bodies().size(), 1u);
    EXPECT_NEAR(world.bodies()[0].position.y, 0.5, 1e-6);
    EXPECT_EQ(world.bodies()[0].position.z, 0.0) << "a prism centred on the plane";
}

}  // namespace

namespace {

using namespace tide;

/// Still water 0.3 m deep in a 2D tank 0.6 m wide at 1 cm, and a box `width` × `height` of
/// `density` floating at Archimedes' draft, turned at `spin` rad/s at the start; the centre of
/// mass `ballast` m above its bottom if > 0.
World tankWithFloatingBox(float width, float height, double density, float spin, float ballast = 0.0f) {
    WorldDef def;
    def.dimensions = 2;
    def.domainMax = {0.6f, 0.55f, 0.0f};
    def.particleSpacing = 0.01f;
    def.threads = 1;
    World world(def);
    world.addMaterial(MaterialDef{});
    const float depth = 0.3f, draft = static_cast<float>(density / 1000.0) * height;
    ObstacleDef box;
    box.min = {0.3f - 0.5f * width, depth - draft, 0.0f};
    box.max = {0.3f + 0.5f * width, depth - draft + height, 0.0f};
    box.name = "box";
    BodyDynamicsDef body;
    body.density = density;
    body.angularVelocity = {0.0f, 0.0f, spin};
    if (ballast > 0.0f) body.centerOfMass = glm::vec3(0.3f, depth - draft + ballast, 0.0f);
    box.dynamics = body;
    world.addObstacle(box);
    BlockDef water;
    water.max = {0.6f, depth, 0.0f};
    world.addBlock(water);
    world.settle(0.3);
    return world;
}

/// A 2D tank `width` wide with still water 0.3 m deep at `spacing`, and a box [x0, x1] × [y0, y1]
/// of density 500, heave only, held while the water settles for 0.3 s.
World tankWithHeavingBox(float width, float spacing, float x0, float x1, float y0, float y1) {
    WorldDef def;
    def.dimensions = 2;
    def.domainMax = {width, 0.5f, 0.0f};
    def.particleSpacing = spacing;
    def.threads = 1;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef box;
    box.min = {x0, y0, 0.0f};
    box.max = {x1, y1, 0.0f};
    BodyDynamicsDef body;
    body.density = 500.0;
    body.freeAxes = {"y"};
    box.dynamics = body;
    world.addObstacle(box);
    BlockDef water;
    water.max = {width, 0.3f, 0.0f};
    world.addBlock(water);
    world.settle(0.3);
    return world;
}

/// The draft of a 2D box 0.1 × 0.1 m of density 500, heave only, centred at `x` in still water
/// 0.3 m deep at 1 cm: its mean over 0.5–1 s after release at Archimedes' draft.
double meanDraftOfAFloatingBox(float x) {
    World world = tankWithHeavingBox(0.6f, 0.01f, x - 0.05f, x + 0.05f, 0.25f, 0.35f);
    world.advance(0.5);
    double sum = 0.0, time = 0.0;
    world.advance(0.5, [&] {
        const double surface = world.surfaceHeight(0.05f, 0.0f), bottom = world.bodies().at(0).position.y - 0.05;
        sum += (surface - bottom) * world.stats().lastDt;
        time += world.stats().lastDt;
    });
    return sum / time;
}

// Acceptance 3 wherever the box stands on the lattice. Its particles once sampled the fluid's
// lattice: with its sides halfway between lattice columns it held ten columns, on them eleven,
// and it floated 0.93 spacings high (a box a spacing wider). It samples its own lattice now.
TEST(FloatingBodies2D, ABoxFloatsAtItsDraftWhereverItsSidesFallOnTheLattice) {
    const double between = meanDraftOfAFloatingBox(0.3f), on = meanDraftOfAFloatingBox(0.305f);
    std::printf("draft of a box of density 500 (0.05 m): %.4f m with its sides between lattice columns, %.4f m on them\n",
                between, on);
    EXPECT_NEAR(between, 0.05, 0.005);
    EXPECT_NEAR(on, 0.05, 0.005);
    EXPECT_NEAR(on, between, 0.0025);
}

double rollDegrees(const BodyState& b) { return 2.0 * std::atan2(b.orientation.z, b.orientation.w) * 180.0 / M_PI; }

// A tall box (0.1 × 0.2 m, density 500) ballasted to a centre of mass 4 cm above its bottom:
// GM = KB + BM − KG = 0.05 + b²/(12 T) − 0.04 = +0.018 m. Rolled past 10° it comes back
// upright and swings about it.
TEST(FloatingBodies2D, ABoxWithPositiveMetacentricHeightRightsItself) {
    World world = tankWithFloatingBox(0.1f, 0.2f, 500.0, 1.3f, 0.04f);
    double largest = 0.0, smallest = 0.0, last = 0.0;
    world.advance(2.0, [&] {
        last = rollDegrees(world.bodies().at(0));
        largest = std::max(largest, last);
        smallest = std::min(smallest, last);
    });
    std::printf("tall box: roll %.2f..%.2f degrees, %.2f at 2 s\n", smallest, largest, last);
    EXPECT_GT(largest, 10.0) << "rolled past 10 degrees";
    EXPECT_LT(smallest, -0.25 * largest) << "came back upright and swung through it";
    EXPECT_LT(std::abs(last), largest);
}

// A square box of density 500: GM = T/2 + b²/(12 T) − H/2 = −H/12 < 0. Upright is unstable;
// nudged, it turns onto its diagonal (45°) and floats there.
TEST(FloatingBodies2D, ASquareBoxOfHalfTheDensityTurnsOntoItsDiagonal) {
    World world = tankWithFloatingBox(0.1f, 0.1f, 500.0, 0.3f);
    std::vector<double> late;
    world.advance(3.0, [&] {
        if (world.time() > 2.0) late.push_back(rollDegrees(world.bodies().at(0)));
    });
    double mean = 0.0;
    for (double a : late) mean += a / static_cast<double>(late.size());
    std::printf("square box: mean roll over 2-3 s %.2f degrees\n", mean);
    EXPECT_NEAR(std::abs(mean), 45.0, 4.5);
}

}  // namespace

namespace {

using namespace tide;

/// Heave decay of a 2D box 0.1 m wide and 0.2 m tall of density 500, heave only, in water
/// 0.3 m deep, released 2 cm above its equilibrium: its centre's height over 1.6 s, as (t, y)
/// pairs. The tank is 2.4 m wide so that the waves the box radiates come back late and weak
/// (the fastest, at √(gd) = 1.7 m/s, after 1.35 s; the main group at ~0.8 m/s after 2.9 s).
/// In a 1.2 m tank they came back within the fit and moved the period by up to 10 %: 0.809,
/// 0.830, 0.789, 0.807 s at 12.5, 10, 6.7 and 5 mm against 0.743, 0.748, 0.731, 0.743 s here.
std::vector<std::pair<double, double>> heaveDecay(float spacing) {
    World world = tankWithHeavingBox(2.4f, spacing, 1.15f, 1.25f, 0.22f, 0.42f);
    const double start = world.time();
    std::vector<std::pair<double, double>> y{{0.0, world.bodies().at(0).position.y}};
    world.advance(1.6, [&] { y.emplace_back(world.time() - start, world.bodies().at(0).position.y); });
    return y;
}

/// The period 2π/ω of the least-squares fit y ≈ c + e^{−βt} (a cos ωt + b sin ωt): linear in
/// (a, b, c) for each (ω, β) of a grid (ω within ±50 % of `guess`, β from 0 to ω).
double fittedPeriod(const std::vector<std::pair<double, double>>& y, double guess) {
    double best = std::numeric_limits<double>::infinity(), period = 0.0;
    for (int i = 0; i <= 500; ++i) {
        const double w = (0.5 + i / 500.0) * 2.0 * M_PI / guess;
        for (int j = 0; j <= 100; ++j) {
            const double beta = w * j / 100.0;
            double m[3][4] = {};  // normal equations [AᵀA | Aᵀy]
            for (const auto& [t, v] : y) {
                const double e = std::exp(-beta * t), row[3] = {e * std::cos(w * t), e * std::sin(w * t), 1.0};
                for (int r = 0; r < 3; ++r) {
                    for (int c = 0; c < 3; ++c) m[r][c] += row[r] * row[c];
                    m[r][3] += row[r] * v;
                }
            }
            for (int k = 0; k < 3; ++k)  // Gauss–Jordan; the system is small and well posed
                for (int r = 0; r < 3; ++r) {
                    if (r == k) continue;
                    const double f = m[r][k] / m[k][k];
                    for (int c = k; c < 4; ++c) m[r][c] -= f * m[k][c];
                }
            double residual = 0.0;
            for (const auto& [t, v] : y) {
                const double e = std::exp(-beta * t);
                const double fit = m[0][3] / m[0][0] * e * std::cos(w * t) + m[1][3] / m[1][1] * e * std::sin(w * t) + m[2][3] / m[2][2];
                residual += (fit - v) * (fit - v);
            }
            if (residual < best) {
                best = residual;
                period = 2.0 * M_PI / w;
            }
        }
    }
    return period;
}

// Acceptance 6: the heave period at 12.5 mm and at 8.3 mm (8 and 12 particles across the box)
// agrees within 3 %. Without added mass it would be 2π √(m / (ρ g b)) = 0.634 s; the water
// moving with the box lengthens it. Measured 0.7662 s at both (0.7606 s at 8.3 mm rounded
// differently in float: the run's scatter is ~0.7 %); 1 cm and 6.7 mm read 0.7736 and 0.7680 s
// (+0.7 %, twice the cost); in a 6 m tank, over four placements of the
// box against the lattice, 0.7731–0.7778 s at 1 cm and 0.7715–0.7731 s at 6.7 mm. While the
// box sampled the fluid's lattice, a placement with its sides on lattice columns (this box at 6.7 mm)
// made it a spacing wider and read anywhere from −4 to +6 %.
TEST(FloatingBodies2D, TheHeavePeriodOfAFloatingBoxConvergesWithResolution) {
    const double undamped = 2.0 * M_PI * std::sqrt(500.0 * 0.1 * 0.2 / (1000.0 * 9.81 * 0.1));
    const double a = fittedPeriod(heaveDecay(0.0125f), undamped), b = fittedPeriod(heaveDecay(0.1f / 12.0f), undamped);
    std::printf("heave period: %.4f s at 12.5 mm, %.4f s at 8.3 mm: %+.2f %% (%.3f s without added mass)\n", a, b,
                100.0 * (a - b) / b, undamped);
    EXPECT_NEAR(a, b, 0.03 * b);
    EXPECT_GT(b, undamped) << "added mass lengthens it";
    EXPECT_LT(b, 1.5 * undamped);
}

}  // namespace
