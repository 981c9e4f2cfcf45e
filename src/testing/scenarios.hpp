#pragma once
/// \file
/// Scene builders shared by tests and benchmarks, so both measure the same setups.

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
/// last `dampingLength` metres. The domain is twice the depth high.
inline World waveFlume(float spacing, float length, float depth, const WaveMakerDef& paddle, float dampingLength,
                       int threads = 0, int widthInSpacings = 4, const SolverDef& solver = {}) {
    WorldDef def;
    def.solver = solver;
    def.domainMin = {0.0f, 0.0f, 0.0f};
    def.domainMax = {length, 2.0f * depth, static_cast<float>(widthInSpacings) * spacing};
    def.periodic = {false, false, true};
    def.particleSpacing = spacing;
    def.threads = threads;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addWaveMaker(paddle);
    if (dampingLength > 0.0f) world.addDampingZone({length - dampingLength, length, 10.0f});
    // Fill from the paddle face; the block's lattice starts half a spacing in front of it.
    world.addBlock({{paddle.x, 0.0f, 0.0f}, {length, depth, def.domainMax.z}, {}, 0});
    return world;
}

}  // namespace tide::scenarios
