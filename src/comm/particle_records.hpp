#pragma once
/// \file
/// Particles as bytes, for another rank: migration hands particles to the rank that owns
/// their cell, ghost exchange sends copies of those near a neighbour's box. Every array of the
/// store travels (`ParticleStore::forEachArray`), so a particle arrives bit for bit as it left,
/// id and solver warm starts included.

#include <cstdint>
#include <span>

#include <tide/particles.hpp>

#include "comm/communicator.hpp"

namespace tide::comm {

/// The particles at `indices` (in that order): a count, then each array's values for them.
Bytes packParticles(const ParticleStore& store, std::span<const std::uint32_t> indices);

/// Appends the particles of `bytes` (made by packParticles) to `store`, ids included, and
/// moves the store's next id past them. Returns how many were appended. Throws
/// std::invalid_argument if the bytes are not a whole record.
std::uint32_t appendPacked(ParticleStore& store, std::span<const std::byte> bytes);

}  // namespace tide::comm
