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

}  // namespace tide::scenarios
