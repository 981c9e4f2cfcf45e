#pragma once
/// \file
/// Private to tide::io: the per-format frame writers that tide::io::writeFrame dispatches
/// to, and a little-endian binary output buffer shared by the binary formats.

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstddef>
#include <cstring>
#include <ostream>
#include <span>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#include <tide/particles.hpp>

namespace tide::io::detail {

/// Writes a frame as CSV: header `x,y,z,vx,vy,vz,density,pressure,material`, one row per particle.
void writeCsv(std::ostream& out, const ParticleStore& particles);
/// Writes a frame as a binary little-endian PLY point cloud (x y z vx vy vz density pressure material id).
void writePly(std::ostream& out, const ParticleStore& particles);
/// Writes a frame as a VTK XML UnstructuredGrid with raw appended data, one VTK_VERTEX cell per point.
void writeVtu(std::ostream& out, const ParticleStore& particles);
/// Writes a parallel VTU file naming `pieces`, each written by writeVtu.
void writePvtu(std::ostream& out, std::span<const std::string> pieces);

/// Appends the shortest decimal form that reads back as exactly `value` (the text formats).
template <class T>
void appendNumber(std::string& line, T value) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    if (ec == std::errc{}) line.append(text, end);
}

/// Buffers trivially copyable values as little-endian bytes and writes them to a stream in
/// large blocks. Call flush() at the end: the destructor does not.
class LittleEndianWriter {
public:
    explicit LittleEndianWriter(std::ostream& out) : out_(out) {}

    /// Appends the bytes of `value`, least significant first.
    template <class T>
    void put(T value) {
        static_assert(std::is_arithmetic_v<T>);
        static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big);
        if (size_ + sizeof(T) > buffer_.size()) flush();
        std::memcpy(buffer_.data() + size_, &value, sizeof(T));
        if constexpr (std::endian::native == std::endian::big) {
            std::reverse(buffer_.data() + size_, buffer_.data() + size_ + sizeof(T));
        }
        size_ += sizeof(T);
    }

    /// Writes the buffered bytes to the stream.
    void flush() {
        if (size_ > 0) out_.write(buffer_.data(), static_cast<std::streamsize>(size_));
        size_ = 0;
    }

private:
    std::ostream& out_;
    std::vector<char> buffer_ = std::vector<char>(std::size_t{1} << 16);  // on the heap: callers may run on small thread stacks
    std::size_t size_ = 0;
};

}  // namespace tide::io::detail
