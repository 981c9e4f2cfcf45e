#include "comm/particle_records.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace tide::comm {

Bytes packParticles(const ParticleStore& store, std::span<const std::uint32_t> indices) {
    const auto count = static_cast<std::uint32_t>(indices.size());
    std::size_t bytesPerParticle = 0;
    store.forEachArray([&](const auto& values) { bytesPerParticle += sizeof(values[0]); });
    Bytes bytes(sizeof count + bytesPerParticle * count);
    std::byte* out = bytes.data();
    std::memcpy(out, &count, sizeof count);
    out += sizeof count;
    store.forEachArray([&](const auto& values) {
        using T = std::decay_t<decltype(values[0])>;
        static_assert(std::is_trivially_copyable_v<T>);
        for (const std::uint32_t i : indices) {
            std::memcpy(out, &values[i], sizeof(T));
            out += sizeof(T);
        }
    });
    return bytes;
}

std::uint32_t appendPacked(ParticleStore& store, std::span<const std::byte> bytes) {
    std::uint32_t count = 0;
    std::size_t bytesPerParticle = 0;
    store.forEachArray([&](const auto& values) { bytesPerParticle += sizeof(values[0]); });
    if (bytes.size() < sizeof count ||
        (std::memcpy(&count, bytes.data(), sizeof count), bytes.size() != sizeof count + bytesPerParticle * count))
        throw std::invalid_argument("particle records: " + std::to_string(bytes.size()) +
                                    " bytes are not a whole record of " + std::to_string(count) + " particles");
    store.makeRoomFor(count);
    const std::byte* in = bytes.data() + sizeof count;
    store.forEachArray([&](auto& values) {
        using T = std::decay_t<decltype(values[0])>;
        const std::size_t first = values.size();
        values.resize(first + count);
        std::memcpy(values.data() + first, in, sizeof(T) * count);
        in += sizeof(T) * count;
    });
    std::uint32_t next = store.nextId();
    for (std::uint32_t k = store.size() - count; k < store.size(); ++k) next = std::max(next, store.id[k] + 1);
    store.setNextId(next);
    return count;
}

}  // namespace tide::comm
