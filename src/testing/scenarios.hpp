#pragma once
/// \file
/// Scene builders shared by tests and benchmarks, so both measure the same setups.

#include <algorithm>
#include <cmath>

#include <tide/world.hpp>

namespace tide::scenarios {

/// A still block of water `depth` deep filling the floor of a box `width` × (2·depth) × width.
inline World stillWater(float depth, float width, float spacing, int threads = 0, const std::string& solver = "classic") {
    WorldDef def;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {width, 2.0f * depth, width};
    def.particleSpacing = spacing;
    def.threads = threads;
    def.solver.method = solver;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0.0f, 0.0f, 0.0f}, {width, depth, width}, {0.0f, 0.0f, 0.0f}, 0});
    return world;
}

/// The narrowest periodic cell, in spacings, that a kernel support allows (two supports), and
/// at least 4.
inline int periodicWidthInSpacings(float supportRatio) {
    return std::max(4, static_cast<int>(std::ceil(2.0f * supportRatio - 1e-4f)));
}

/// The support ratio a world with `solver` and `supportRatio` (0: automatic) gets in
/// `dimensions` (resolveAutomaticKernel).
inline float resolvedSupportRatio(const SolverDef& solver, float supportRatio, int dimensions = 3) {
    WorldDef def;
    def.dimensions = dimensions;
    def.solver = solver;
    def.supportRatio = supportRatio;
    return withResolvedKernel(def).supportRatio;
}

/// Still water `depth` deep in a tank `length` long and twice the depth high, walls across x
/// (or periodic, if `def` makes x periodic); across z one periodic cell `widthInSpacings`
/// spacings wide (2D), or with `closed` walls and a square floor. With `def.dimensions` 2 the
/// tank is the plane z = 0 (widthInSpacings and closed then say nothing). Spacing, support,
/// gravity, solver and threads come from `def`.
inline World stillTank(WorldDef def, float length, float depth, int widthInSpacings, bool closed = false) {
    const bool planar = def.dimensions == 2;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {length, 2.0f * depth,
                     planar ? 0.0f : closed ? length : static_cast<float>(widthInSpacings) * def.particleSpacing};
    def.periodic.y = false;
    def.periodic.z = !closed && !planar;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0.0f, 0.0f, 0.0f}, {length, depth, def.domainMax.z}, {}, 0});
    return world;
}

/// A dam break: a water column `column` wide and high in a corner of a tank `length` long.
inline World damBreak(float spacing, int threads = 0, float length = 1.6f, float column = 0.4f, float width = 0.4f,
                       int reorderInterval = WorldDef{}.reorderInterval, const std::string& solver = "classic") {
    WorldDef def;
    def.reorderInterval = reorderInterval;
    def.solver.method = solver;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {length, 2.0f * column, width};
    def.particleSpacing = spacing;
    def.threads = threads;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addBlock({{0.0f, 0.0f, 0.0f}, {column, column, width}, {0.0f, 0.0f, 0.0f}, 0});
    return world;
}

/// A numerical wave flume: water `depth` deep in a tank `length` long, one periodic cell of
/// `width` (a whole number of spacings, ≥ 4) across z, so it behaves as a 2D flume without
/// side-wall friction; a wave maker with its face at `paddle.x` and a damping zone over the
/// last `dampingLength` metres. The domain is twice the depth high. `supportRatio` 0: the default.
inline World waveFlume(float spacing, float length, float depth, const WaveMakerDef& paddle, float dampingLength,
                       int threads = 0, int widthInSpacings = 4, const SolverDef& solver = {}, float supportRatio = 0.0f,
                       const MaterialDef& water = {}) {
    WorldDef def;
    def.solver = solver;
    if (supportRatio > 0.0f) def.supportRatio = supportRatio;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {length, 2.0f * depth, static_cast<float>(widthInSpacings) * spacing};
    def.periodic = {false, false, true};
    def.particleSpacing = spacing;
    def.threads = threads;
    World world(def);
    world.addMaterial(water);
    world.addWaveMaker(paddle);
    if (dampingLength > 0.0f) world.addDampingZone({length - dampingLength, length, 10.0f});
    // Fill from the paddle face; the block's lattice starts half a spacing in front of it.
    world.addBlock({{paddle.x, 0.0f, 0.0f}, {length, depth, def.domainMax.z}, {}, 0});
    return world;
}

/// A 2D flume (WorldDef::dimensions = 2) `length` long with water `depth` deep from the
/// paddle's face to the far wall, which reflects every wave, or to a damping zone
/// `dampingLength` long before it; the paddle's own settings (absorption included) as given.
inline World planarFlume(float spacing, float length, const WaveMakerDef& paddle, float dampingLength = 0.0f,
                         int threads = 0, const SolverDef& solver = {}) {
    WorldDef def;
    def.dimensions = 2;
    def.solver = solver;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {length, 2.0f * paddle.depth, 0.0f};
    def.particleSpacing = spacing;
    def.threads = threads;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addWaveMaker(paddle);
    if (dampingLength > 0.0f) world.addDampingZone({length - dampingLength, length, 10.0f});
    world.addBlock({{paddle.x, 0.0f, 0.0f}, {length, paddle.depth, 0.0f}, {}, 0});
    return world;
}

/// A plate pushed through still water: a flume `length` long with water `depth` deep, one
/// periodic cell of 4 spacings across z (2D), and a plate 4 spacings thick standing on the
/// floor in the middle, 2.5 depths high, that moves along +x at `speed` after a 0.1 s ramp.
inline World pushedPlate(float spacing, float length, float depth, float speed, int threads = 0,
                         const std::string& solver = "dfsph") {
    WorldDef def;
    def.solver.method = solver;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {length, 3.0f * depth, 4.0f * spacing};
    def.periodic = {false, false, true};
    def.particleSpacing = spacing;
    def.threads = threads;
    World world(def);
    world.addMaterial(MaterialDef{});
    ObstacleDef plate;
    plate.shape = ObstacleDef::Shape::Box;
    plate.min = {0.5f * length - 2.0f * spacing, 0.0f, 0.0f};
    plate.max = {0.5f * length + 2.0f * spacing, 2.5f * depth, def.domainMax.z};
    plate.motion.type = MotionDef::Type::Translation;
    plate.motion.velocity = {speed, 0.0f, 0.0f};
    plate.motion.rampTime = 0.1f;
    world.addObstacle(plate);
    world.addBlock({{0.0f, 0.0f, 0.0f}, {length, depth, def.domainMax.z}, {}, 0});
    return world;
}

/// A cylinder of `radius` spinning at `omega` rad/s (after a 0.1 s ramp) about the y axis in
/// the middle of a square box `width` wide, filled with a fluid of dynamic viscosity `mu`
/// (ρ0 = 1000), without gravity; y is one periodic cell of 4 spacings (2D, Couette-like).
inline World spinningCylinder(float spacing, float width, float radius, float omega, float mu, int threads = 0,
                              const std::string& solver = "dfsph") {
    WorldDef def;
    def.solver.method = solver;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {width, 4.0f * spacing, width};
    def.periodic = {false, true, false};
    def.gravity = {0.0f, 0.0f, 0.0f};
    def.particleSpacing = spacing;
    def.threads = threads;
    World world(def);
    MaterialDef fluid;
    fluid.viscosity = mu;
    world.addMaterial(fluid);
    ObstacleDef cylinder;
    cylinder.shape = ObstacleDef::Shape::Cylinder;
    cylinder.center = {0.5f * width, 2.0f * spacing, 0.5f * width};
    cylinder.axis = {0.0f, 1.0f, 0.0f};
    cylinder.radius = radius;
    cylinder.length = 8.0f * spacing;  // longer than the period: no caps inside the fluid
    cylinder.motion.type = MotionDef::Type::Rotation;
    cylinder.motion.axis = cylinder.axis;
    cylinder.motion.center = cylinder.center;
    cylinder.motion.angularVelocity = omega;
    cylinder.motion.rampTime = 0.1f;
    world.addObstacle(cylinder);
    world.addBlock({def.domainMin, def.domainMax, {}, 0});
    return world;
}

}  // namespace tide::scenarios
