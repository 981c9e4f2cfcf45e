#pragma once
/// \file
/// A continuous source (the seed's `addPointTick`). It integrates the distance its stream
/// has travelled in floating point and emits a layer each time that reaches one spacing,
/// placing the layer as far downstream as it has travelled since it was due. Layers are
/// therefore exactly one spacing apart whatever the step or frame length.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include <tide/defs.hpp>

#include "sources/lattice.hpp"

namespace tide {

struct EmitterState {
    EmitterDef def;
    bool active = true;
    double travelled = -1.0;  ///< stream length since the last layer, m; < 0 until the first step

    /// Account for a step [t0, t0 + dt]; calls emitLayer(lattice) for every layer due, oldest
    /// first, until it returns false (the world is full). Returns the layers dropped then: all
    /// still due, dropped at once rather than tried one by one (a fast jet may owe millions).
    template <class EmitLayer>
    double advance(double t0, double dt, float spacing, EmitLayer&& emitLayer) {
        if (!active) return 0.0;
        const double overlap = std::min(t0 + dt, def.end) - std::max(t0, def.start);
        if (overlap <= 0.0) return 0.0;
        if (travelled < 0.0) travelled = spacing;  // the first active step emits at once
        const double speed = glm::length(def.velocity);
        travelled += speed * overlap;
        const glm::vec3 direction = def.velocity / static_cast<float>(speed);
        while (travelled >= spacing) {
            travelled -= spacing;
            const glm::vec3 shift = direction * static_cast<float>(travelled);
            if (!emitLayer(Lattice(def.min + shift, def.max + shift, spacing))) {
                const double dropped = std::floor(travelled / spacing);
                travelled -= dropped * spacing;
                return 1.0 + dropped;
            }
        }
        return 0.0;
    }
};

}  // namespace tide
