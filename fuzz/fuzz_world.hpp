#pragma once
// The small world the checkpoint fuzzer restores states into, and checkpoint_seed saves
// seeds from: every part a checkpoint carries (dfsph's scalar, an emitter, a wave paddle).
#include <tide/world.hpp>

namespace tide::fuzzing {

inline World smallWorld() {
    WorldDef def;
    def.domainMax = {0.4f, 0.2f, 0.08f};
    def.periodic = {false, false, true};
    def.particleSpacing = 0.02f;
    def.threads = 1;
    World world(def);
    world.addMaterial(MaterialDef{});
    world.addMaterial(MaterialDef{"oil", 900.0f, 0.01f, {1.0f, 0.8f, 0.2f}});
    WaveMakerDef paddle;
    paddle.x = 0.05f;
    paddle.depth = 0.06f;
    paddle.waveHeight = 0.01f;
    paddle.period = 0.5f;
    world.addWaveMaker(paddle);
    world.addBlock({{0.05f, 0.0f, 0.0f}, {0.25f, 0.06f, 0.08f}, {}, 0});
    world.addBlock({{0.25f, 0.0f, 0.0f}, {0.4f, 0.04f, 0.08f}, {}, 1});
    EmitterDef jet;
    jet.min = {0.3f, 0.12f, 0.02f};
    jet.max = {0.3f, 0.14f, 0.06f};
    jet.velocity = {-0.5f, 0.0f, 0.0f};
    world.addEmitter(jet);
    return world;
}

}  // namespace tide::fuzzing
